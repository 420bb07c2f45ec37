#include "render/PolarisationEllipse.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope::render {

namespace {

constexpr int kEllipseSegments = 64;

void addEllipse(LineBatch& lines, const Point& at, const Eigen::Vector3d& major, const Eigen::Vector3d& minor,
                const Colour& colour) {
    const auto point = [&](int k) {
        const double t = 2.0 * std::numbers::pi * k / kEllipseSegments;
        return Point(at + std::cos(t) * major + std::sin(t) * minor);
    };
    for (int k = 0; k < kEllipseSegments; ++k) lines.add(point(k), point(k + 1), colour);
}

}  // namespace

EllipseShape polarisationEllipse(const StokesVector& stokes) {
    const double polarised = stokes.tail<3>().norm();
    EllipseShape shape;
    shape.degree = degreeOfPolarisation(stokes);
    shape.orientation = 0.5 * std::atan2(stokes[2], stokes[1]);
    if (polarised > 0.0) shape.ellipticity = 0.5 * std::asin(std::clamp(stokes[3] / polarised, -1.0, 1.0));
    return shape;
}

void addPolarisationEllipse(LineBatch& lines, const Point& at, const Direction& direction, const Polarisation& light,
                            double size) {
    const Eigen::Vector3d& k = direction.vector();
    // The frame's axes, the reference made exactly perpendicular to k should it be off by rounding.
    const Eigen::Vector3d parallel = (light.reference - light.reference.dot(k) * k).normalized();
    const Eigen::Vector3d perpendicular = perpendicularAxis(parallel, direction);
    const EllipseShape shape = polarisationEllipse(light.stokes);
    const bool polarised = shape.degree >= kUnpolarisedDegree;
    if (polarised) {
        const double psi = shape.orientation;
        const Eigen::Vector3d majorAxis = std::cos(psi) * parallel + std::sin(psi) * perpendicular;
        const Eigen::Vector3d minorAxis = -std::sin(psi) * parallel + std::cos(psi) * perpendicular;
        addEllipse(lines, at, size * majorAxis, size * std::abs(std::tan(shape.ellipticity)) * minorAxis,
                   kEllipseColour);
    }
    lines.add(at, at + size * k, polarised ? kEllipseColour : kUnpolarisedColour);
    addEllipse(lines, at, size * parallel, size * perpendicular, kUnpolarisedColour);
}

}  // namespace dropscope::render
