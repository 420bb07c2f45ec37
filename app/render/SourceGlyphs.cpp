#include "render/SourceGlyphs.hpp"

#include "transport/Emission.hpp"

#include <numbers>

namespace dropscope::render {

namespace {

constexpr int kCircleSegments = 48;
constexpr double kHeadLength = 0.2;  // of the arrow
constexpr double kHeadWidth = 0.08;  // of the arrow, each side

void addArrow(LineBatch& lines, const Point& origin, const Direction& direction, double length) {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicularBasis(direction, u, v);
    const Point tip = origin + length * direction.vector();
    lines.add(origin, tip, kSourceColour);
    const Point base = tip - kHeadLength * length * direction.vector();
    for (const Eigen::Vector3d& side : {u, v, Eigen::Vector3d(-u), Eigen::Vector3d(-v)}) {
        lines.add(tip, base + kHeadWidth * length * side, kSourceColour);
    }
}

void addCircle(LineBatch& lines, const Point& center, const Direction& normal, double radius) {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicularBasis(normal, u, v);
    const auto at = [&](int k) {
        const double phi = 2.0 * std::numbers::pi * k / kCircleSegments;
        return Point(center + radius * (std::cos(phi) * u + std::sin(phi) * v));
    };
    for (int k = 0; k < kCircleSegments; ++k) lines.add(at(k), at(k + 1), kSourceColour);
}

void addStar(LineBatch& lines, const Point& center, double halfWidth) {
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d offset = halfWidth * Eigen::Vector3d::Unit(axis);
        lines.add(center - offset, center + offset, kSourceColour);
    }
}

}  // namespace

void addSourceGlyphs(LineBatch& lines, const std::vector<Source>& sources, double size) {
    for (const Source& source : sources) {
        switch (source.type) {
        case SourceType::Beam:
            addArrow(lines, source.origin, source.direction, size);
            addCircle(lines, source.origin, source.direction, source.radius);
            break;
        case SourceType::Ray: addArrow(lines, source.origin, source.direction, size); break;
        case SourceType::PointSource: addStar(lines, source.origin, 0.25 * size); break;
        }
    }
}

}  // namespace dropscope::render
