#include "gui/SourceReference.hpp"

#include "optics/OpticsTolerance.hpp"
#include "transport/Emission.hpp"

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
    // The least aligned axis's part across the direction: perpendicularBasis's v.
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicularBasis(direction, u, v);
    return v;
}

std::string keepReferencePerpendicular(Source& source) {
    Eigen::Vector3d& reference = source.polarisation.reference;
    if (source.polarisation.kind == PolarisationKind::Unpolarised || source.type == SourceType::PointSource) return {};
    const Eigen::Vector3d& k = source.direction.vector();
    const Direction unit(reference);  // normalised without overflow or underflow; invalid for zero or non-finite
    if (unit && std::abs(unit.dot(k)) <= tolerance::kReferencePerpendicularCosine) return {};
    const Eigen::Vector3d across = unit ? Eigen::Vector3d(unit.vector() - unit.dot(k) * k) : Eigen::Vector3d::Zero();
    if (unit && across.norm() > kAlongDirection) {
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
