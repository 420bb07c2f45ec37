#include "transport/SurfaceCrossing.hpp"

#include "optics/Fresnel.hpp"
#include "optics/Interface.hpp"

#include <cmath>

namespace dropscope {

std::string_view polarisationModelName(PolarisationModel model) {
    return model == PolarisationModel::None ? "none" : "stokes";
}

SurfaceCrossing crossSurface(const OpticalScene& scene, ShapeId region, ShapeId shape, const Point& point,
                             const Direction& direction, FresnelModel fresnel, bool unpolarisedReflectance,
                             std::span<const MediumOptics> optics) {
    SurfaceCrossing crossing;
    const Direction normal = scene.normalOf(shape, point);
    if (!normal) {
        crossing.lostReason = LostReason::UndefinedNormal;
        return crossing;
    }
    const double cosine = direction.dot(normal);
    if (cosine == 0.0) {
        crossing.kind = SurfaceCrossing::Kind::Tangent;
        return crossing;
    }
    const bool entering = cosine < 0.0;
    const ShapeId expectedRegion = entering ? scene.parentOf(shape) : shape;
    if (region != expectedRegion) return crossing;  // MediumMismatch

    crossing.kind = SurfaceCrossing::Kind::Interface;
    crossing.regionBeyond = entering ? shape : scene.parentOf(shape);
    crossing.from = scene.mediumIdOf(region);
    crossing.to = scene.mediumIdOf(crossing.regionBeyond);
    if (optics.empty()) optics = scene.sceneOptics();
    const double n1 = optics[crossing.from].n;
    const double n2 = optics[crossing.to].n;
    crossing.normal = normal;
    crossing.cosIncidence = std::abs(cosine);
    crossing.n1 = n1;
    crossing.n2 = n2;
    crossing.incident = direction;
    const Refraction refraction = refract(direction, normal, n1, n2);
    if (refraction.outcome == InterfaceOutcome::TotalInternalReflection) {
        crossing.totalInternalReflection = true;
        return crossing;
    }
    crossing.transmitted = refraction.transmitted;
    if (!unpolarisedReflectance) {
        crossing.reflectance = std::nan("");
        return crossing;
    }
    const double cosIncidence = crossing.cosIncidence;
    crossing.reflectance = fresnel == FresnelModel::Exact ? fresnelReflectance(cosIncidence, n1, n2).unpolarised()
                                                          : schlickReflectance(cosIncidence, n1, n2);
    return crossing;
}

}  // namespace dropscope
