#pragma once

#include "geometry/RayQuadric.hpp"
#include "geometry/Tolerance.hpp"
#include "geometry/Vector.hpp"

#include <cmath>

namespace dropscope {

// A sphere's numbers and its point/ray rules as plain inline functions: Sphere forwards to them, and
// the octree runs the very same code on spheres it packs by value, so both give bit-identical answers.
struct SphereGeometry {
    Point center;
    double radius;
    double band;  // surface band half-width, tolerance::surfaceBand(radius, |center|_inf)

    static SphereGeometry make(const Point& center, double radius) {
        return {center, radius, tolerance::surfaceBand(radius, center.cwiseAbs().maxCoeff())};
    }

    PointLocation locate(const Point& p) const {
        const double signedDistance = (p - center).norm() - radius;  // seed eq. 1.5
        if (std::isnan(signedDistance)) return PointLocation::Outside;
        if (std::abs(signedDistance) <= band) return PointLocation::OnSurface;
        return signedDistance < 0.0 ? PointLocation::Inside : PointLocation::Outside;
    }

    double distanceToSurface(const Point& p, const Direction& d) const {
        if (!d || !p.allFinite()) return std::nan("");
        // seed eqs. 1.10-1.12: s^2 + 2Bs + C = 0
        const Eigen::Vector3d offset = p - center;
        const double b = offset.dot(d.vector());
        const double c = offset.squaredNorm() - radius * radius;
        // B^2 - C = R^2 - |offset - B d|^2: the squared half-chord, free of the cancellation in B^2 - C.
        const double perpendicular = (offset - b * d.vector()).norm();
        const double discriminant = (radius - perpendicular) * (radius + perpendicular);
        return quadricDistance({1.0, b, c, discriminant}, locate(p), band);
    }
};

}  // namespace dropscope
