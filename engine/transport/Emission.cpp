#include "transport/Emission.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {

void perpendicularBasis(const Direction& d, Eigen::Vector3d& u, Eigen::Vector3d& v) {
    // Cross with the axis least aligned with d, so the product is never short.
    Eigen::Index smallest = 0;
    d.vector().cwiseAbs().minCoeff(&smallest);
    u = Eigen::Vector3d::Unit(smallest).cross(d.vector()).normalized();
    v = d.vector().cross(u);
}

Polarisation unpolarisedLight(const Direction& direction) {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicularBasis(direction, u, v);
    return {unpolarisedStokes(), u};
}

Polarisation emittedPolarisation(const Source& source, const Direction& direction) {
    const SourcePolarisation& polarisation = source.polarisation;
    if (polarisation.kind == PolarisationKind::Unpolarised) return unpolarisedLight(direction);
    const Direction r(polarisation.reference);  // normalised first: any finite length
    const Direction across(r.vector() - r.dot(direction.vector()) * direction.vector());
    if (!across) throw std::invalid_argument("a polarisation reference must be a finite vector across the direction");
    return {polarisation.unitStokes(), across.vector()};
}

Ray emitPhoton(const Source& source, PhotonRandom& random) {
    switch (source.type) {
    case SourceType::Ray: return {source.origin, source.direction};
    case SourceType::Beam: {
        Eigen::Vector3d u;
        Eigen::Vector3d v;
        perpendicularBasis(source.direction, u, v);
        const double r = source.radius * std::sqrt(random.uniform());
        const double phi = 2.0 * std::numbers::pi * random.uniform();
        return {source.origin + r * (std::cos(phi) * u + std::sin(phi) * v), source.direction};
    }
    case SourceType::PointSource: {
        const double z = 1.0 - 2.0 * random.uniform();
        const double phi = 2.0 * std::numbers::pi * random.uniform();
        const double s = std::sqrt((1.0 - z) * (1.0 + z));
        return {source.origin, Direction(s * std::cos(phi), s * std::sin(phi), z)};
    }
    }
    return {source.origin, source.direction};
}

Direction directionInCone(const Direction& axis, double halfAngleDeg, PhotonRandom& random) {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicularBasis(axis, u, v);
    const double halfSine = std::sin(0.5 * halfAngleDeg * (std::numbers::pi / 180.0));
    const double oneMinusCos = 2.0 * halfSine * halfSine * random.uniform();  // 1 - cos theta
    const double cosTheta = 1.0 - oneMinusCos;
    const double sinTheta = std::sqrt(oneMinusCos * (1.0 + cosTheta));
    const double phi = 2.0 * std::numbers::pi * random.uniform();
    return Direction(cosTheta * axis.vector() + sinTheta * (std::cos(phi) * u + std::sin(phi) * v));
}

EmittedLight emitLight(const Source& source, const Spectrum& spectrum, PhotonRandom& sourceRandom) {
    EmittedLight light;
    light.wavelengthNm =
        spectrum.drawsRandomNumbers() ? spectrum.sample(sourceRandom.uniform()) : spectrum.rangeNm().first;
    light.direction = source.divergenceDeg > 0.0 ? directionInCone(source.direction, source.divergenceDeg, sourceRandom)
                                                 : source.direction;
    return light;
}

}  // namespace dropscope
