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

}  // namespace dropscope
