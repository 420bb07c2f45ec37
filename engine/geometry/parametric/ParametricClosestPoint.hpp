#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/Vector.hpp"
#include "geometry/parametric/ParametricBase.hpp"

#include <limits>

namespace dropscope {

// The point of a placed parametric surface nearest to a given point.
struct SurfaceProjection {
    double u = 0.0;  // folded into the domain
    double v = 0.0;
    double distance = std::numeric_limits<double>::infinity();  // +inf: nothing within the cutoff
};

// The least-squares solution of p = M r(u, v) + r0 (seed 000 eqs. 1.74, 1.75): min |p - M r(u, v) - r0| by
// Levenberg-Marquardt, among the surface points within `cutoff` of p (+inf: the global minimum).
// Global by branch and bound: cells are examined in order of the distance from p to their (placed) box, each by a
// run confined to the cell slightly enlarged and started at its centre, until the next box is farther than the
// best point found (or than the cutoff).
SurfaceProjection closestSurfacePoint(const ParametricBase& base, const AffineTransform& transform, const Point& p,
                                      double cutoff = std::numeric_limits<double>::infinity());

}  // namespace dropscope
