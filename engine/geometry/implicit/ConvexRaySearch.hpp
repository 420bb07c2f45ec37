#pragma once

#include "geometry/implicit/ImplicitFunction.hpp"

namespace dropscope {

// The answer of a search along a ray through a convex body.
struct ConvexRayResult {
    enum class Status {
        Found,   // t is the crossing
        None,    // certified: no such crossing in the interval
        Failed,  // the convexity argument broke down (non-finite values, no convergence): use RayRootFinder
    };
    Status status = Status::Failed;
    double t = 0.0;
};

// Crossings of g(t) = f(origin + t direction) when f is convex (ImplicitFunction::convexCentre), so that g
// is convex in t and the body meets the ray in one interval. Any tangent of a convex g lies below it
// (with grad f a subgradient where f is not differentiable), which gives, at an outside point t (g > 0)
// with slope m = grad f . direction:
//   m < 0: the entry is at or beyond the Newton point t + g / |m| (and the exit before the Newton point
//          of any outside point right of the body); m >= 0: g > 0 everywhere beyond t.
// So Newton from either end of an outside interval converges monotonically onto the crossings without
// overshooting them, and the Lipschitz stepper's tiny steps along a ray grazing a flat face are avoided:
// the two tangents at the ends certify a miss at once when their zeros cross. `direction` need not be unit.

// The entry into the body in [tBegin, tEnd], both ends outside (g(tBegin) >= 0, g(tEnd) > 0). Found when
// the ray passes through the body: the entry t (refined to `tolerance`, on its outside) with the exit
// beyond t + band; None when it misses or only touches (a chord no longer than `band`, the rule of
// ImplicitShape::distanceToSurface). Newton from the left; when it slows down (a tangent approach, or
// high-order contact with a flat face), Newton from the right and a bisection on the sign of g' halve the
// interval that can still hold the chord, so the cost is bounded by ~log2(length / band) steps.
ConvexRayResult convexEntry(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction,
                            double tBegin, double tEnd, double band, double tolerance);

// The exit from the body beyond tAfter, with g(tEnd) > 0: Newton from the right end, bisection on the
// signs of g and g' when it slows down. Found (refined to `tolerance`, on its outside), or None when the
// ray leaves the body before tAfter or never enters it (from an inside tAfter, None only by rounding).
ConvexRayResult convexExit(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction,
                           double tAfter, double tEnd, double tolerance);

}  // namespace dropscope
