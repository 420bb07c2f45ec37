#pragma once

#include "geometry/Shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope {

// a s^2 + 2 b s + c = 0 along a ray p + s d, for a quadric surface (sphere, ellipsoid).
// `discriminant` is b^2 - a c, which the caller computes in a cancellation-free form.
struct RayQuadratic {
    double a;
    double b;
    double c;
    double discriminant;
};

// The seed's distance semantics (seed 000 ch. 1 item 7) applied to the roots of a RayQuadratic, given where
// the ray starts. `chordBand` is the surface band in length units: a chord no longer than it is a
// tangent touch (outside: NaN; on the surface: 0), so a hit point never re-hits its own surface at ~0.
// Inline: it sits on the octree's innermost loop.
inline double quadricDistance(const RayQuadratic& q, PointLocation start, double chordBand) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    const double root = std::sqrt(std::max(q.discriminant, 0.0));
    switch (start) {
    case PointLocation::Inside:
        // c < 0: one root of each sign; take the positive one without cancellation.
        return q.b <= 0.0 ? (-q.b + root) / q.a : -q.c / (q.b + root);
    case PointLocation::OnSurface: {
        if (q.b >= 0.0) return 0.0;  // leaving or tangent
        const double farSide = (-q.b + root) / q.a;
        return farSide > chordBand ? farSide : 0.0;
    }
    case PointLocation::Outside:
        if (q.b >= 0.0 || q.discriminant <= 0.0) return kNaN;  // moving away, or missing
        if (2.0 * root / q.a <= chordBand) return kNaN;        // grazing touch: never enters
        return q.c / (-q.b + root);                            // nearer root, cancellation-free
    }
    return kNaN;
}

}  // namespace dropscope
