#include "gui/SourceReference.hpp"

#include "optics/OpticsTolerance.hpp"

#include <cmath>
#include <cstdio>

namespace dropscope::gui {

namespace {

// A reference whose part across the direction is shorter than this fraction of it lies along the
// direction for any use: its projection would point wherever rounding takes it.
constexpr double kAlongDirection = 1e-6;

std::string vectorText(const Eigen::Vector3d& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z());
    return text;
}

}  // namespace

Eigen::Vector3d perpendicularReference(const Direction& direction) {
    Eigen::Index least = 0;
    direction.vector().cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(least);
    return (axis - axis.dot(direction.vector()) * direction.vector()).normalized();
}

std::string keepReferencePerpendicular(Source& source) {
    Eigen::Vector3d& reference = source.polarisation.reference;
    if (source.polarisation.kind == PolarisationKind::Unpolarised || source.type == SourceType::PointSource) return {};
    const Eigen::Vector3d& k = source.direction.vector();
    const double length = reference.norm();
    if (reference.allFinite() && length > 0.0 &&
        std::abs(reference.dot(k)) <= tolerance::kReferencePerpendicularCosine * length) {
        return {};
    }
    const Eigen::Vector3d across = reference - reference.dot(k) * k;
    if (reference.allFinite() && length > 0.0 && across.norm() > kAlongDirection * length) {
        reference = across.normalized();
        return "polarisation reference projected across the direction: " + vectorText(reference);
    }
    reference = perpendicularReference(source.direction);
    return "polarisation reference set perpendicular to the direction: " + vectorText(reference);
}

std::string aimSource(Source& source, const Direction& direction) {
    source.direction = direction;
    return keepReferencePerpendicular(source);
}

}  // namespace dropscope::gui
