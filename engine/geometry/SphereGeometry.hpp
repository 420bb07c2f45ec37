#pragma once

#include "geometry/RayQuadric.hpp"
#include "geometry/Tolerance.hpp"
#include "geometry/Vector.hpp"

#include <cmath>
#include <limits>

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
        const double distanceSquared = offset.squaredNorm();
        const double c = distanceSquared - radius * radius;
        // B^2 - C = R^2 - |offset - B d|^2: the squared half-chord, free of the cancellation in B^2 - C.
        const double perpendicularSquared = (offset - b * d.vector()).squaredNorm();
        // Most calls in a cloud are misses: when p is surely outside (locate would say so) and the ray
        // moves away or passes by, answer NaN before any square root, as quadricDistance would. The
        // 1e-12 keeps the shortcut clear of the rounding at both thresholds.
        const double outer = radius + 2.0 * band;
        if (distanceSquared > outer * outer * (1.0 + 1e-12) &&
            (b >= 0.0 || perpendicularSquared > radius * radius * (1.0 + 1e-12))) {
            return std::numeric_limits<double>::quiet_NaN();
        }
        const double perpendicular = std::sqrt(perpendicularSquared);
        const double discriminant = (radius - perpendicular) * (radius + perpendicular);
        return quadricDistance({1.0, b, c, discriminant}, locate(p), band);
    }
};

}  // namespace dropscope
