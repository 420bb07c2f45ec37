#pragma once

#include "geometry/Shape.hpp"

namespace dropscope {

// a s^2 + 2 b s + c = 0 along a ray p + s d, for a quadric surface (sphere, ellipsoid).
// `discriminant` is b^2 - a c, which the caller computes in a cancellation-free form.
struct RayQuadratic {
    double a;
    double b;
    double c;
    double discriminant;
};

// The seed's distance semantics (1.2.7, 1.3.7) applied to the roots of a RayQuadratic, given where
// the ray starts. `chordBand` is the surface band in length units: a chord no longer than it is a
// tangent touch (outside: NaN; on the surface: 0), so a hit point never re-hits its own surface at ~0.
double quadricDistance(const RayQuadratic& q, PointLocation start, double chordBand);

}  // namespace dropscope
