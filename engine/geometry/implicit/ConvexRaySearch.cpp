#include "geometry/implicit/ConvexRaySearch.hpp"

#include "geometry/implicit/ImplicitTolerance.hpp"
#include "geometry/implicit/RayRootFinder.hpp"

#include <cmath>
#include <limits>

namespace dropscope {

namespace {

using tolerance::implicit::kConvexRayIterations;
using tolerance::implicit::kConvexSlowProgress;

// g and its slope g' = grad f . direction at one t (a subgradient where f has a kink).
struct Sample {
    double t = 0.0;
    double g = 0.0;
    double slope = 0.0;
    bool finite() const { return std::isfinite(g) && std::isfinite(slope); }
};

class ConvexRay {
public:
    ConvexRay(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction)
        : f_(f), origin_(origin), direction_(direction) {}

    double value(double t) const { return f_.value(origin_ + t * direction_); }
    Sample sample(double t) const {
        const Point r = origin_ + t * direction_;
        return {t, f_.value(r), f_.gradient(r).dot(direction_)};
    }
    // The crossing between an outside and an inside sample, in either order (safeguarded Newton and
    // bisection on the bracket).
    double refine(const Sample& a, const Sample& b, double tolerance) const {
        const Sample& left = a.t < b.t ? a : b;
        const Sample& right = a.t < b.t ? b : a;
        return refineCrossing(f_, origin_, direction_, left.t, left.g, right.t, right.g, tolerance).t;
    }

private:
    const ImplicitFunction& f_;
    Point origin_;
    Eigen::Vector3d direction_;
};

ConvexRayResult found(double t) { return {ConvexRayResult::Status::Found, t}; }
ConvexRayResult none() { return {ConvexRayResult::Status::None, 0.0}; }
ConvexRayResult failed() { return {ConvexRayResult::Status::Failed, 0.0}; }

}  // namespace

ConvexRayResult convexExit(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction,
                           double tAfter, double tEnd, double tolerance) {
    const ConvexRay ray(f, origin, direction);
    Sample hi = ray.sample(tEnd);  // outside, right of the exit: exit <= every Newton point from here
    if (!hi.finite() || !(hi.g > 0.0)) return failed();
    double lo = tAfter;  // the exit, if any, lies beyond
    double previousStep = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < kConvexRayIterations; ++iteration) {
        // Outside and not increasing: g >= g(hi) > 0 everywhere before hi.
        if (!(hi.slope > 0.0)) return none();
        const double b = hi.t - hi.g / hi.slope;
        if (b <= lo) return none();  // exit <= b <= lo
        const double step = hi.t - b;
        if (step <= tolerance) return found(b);
        Sample s = ray.sample(b);
        if (!s.finite()) return failed();
        if (s.g < 0.0) return found(ray.refine(s, hi, tolerance));  // rounding put b just inside
        hi = s;
        if (step > kConvexSlowProgress * previousStep && hi.slope > 0.0) {
            // Slow (a tangent exit, a flat contact): bisect. Inside, or outside and still descending
            // (left of the minimum), the exit lies beyond the middle; outside and ascending, before it.
            const double middle = 0.5 * (lo + hi.t);
            s = ray.sample(middle);
            if (!s.finite()) return failed();
            if (s.g < 0.0 || s.slope <= 0.0) {
                lo = middle;
            } else {
                hi = s;
            }
        }
        previousStep = step;
    }
    return failed();
}

ConvexRayResult convexEntry(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction,
                            double tBegin, double tEnd, double band, double tolerance) {
    const ConvexRay ray(f, origin, direction);
    // lo: outside, left of the entry (g >= 0, g' < 0); hi: outside, right of the exit (g > 0, g' > 0).
    Sample lo = ray.sample(tBegin);
    Sample hi = ray.sample(tEnd);
    if (!lo.finite() || !hi.finite() || !(lo.g >= 0.0) || !(hi.g > 0.0)) return failed();

    // An entry counts when the body holds a point beyond entry + band (the chord is longer than a band):
    // a known inside point that far, g(entry + band) < 0, or else an exit beyond entry + band. The exit
    // search settles rays entering at a grazing angle, where g(entry + band) is rounding noise.
    const auto passage = [&](double entry, double insideT) {
        if (insideT - entry > band) return found(entry);  // false for a NaN insideT
        const double g = ray.value(entry + band);
        if (std::isnan(g)) return failed();
        if (g < 0.0) return found(entry);
        const ConvexRayResult exit = convexExit(f, origin, direction, entry + band, tEnd, tolerance);
        if (exit.status == ConvexRayResult::Status::Failed) return failed();
        return exit.status == ConvexRayResult::Status::Found ? found(entry) : none();
    };
    constexpr double kNoInsidePoint = std::numeric_limits<double>::quiet_NaN();
    double previousStep = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < kConvexRayIterations; ++iteration) {
        // Convex and not decreasing at lo (not increasing at hi): positive on the whole rest of the ray.
        if (lo.slope >= 0.0 || hi.slope <= 0.0) return none();
        // The tangents' zeros a <= entry <= exit <= b. Crossed zeros (or an overflowing step): no root;
        // closer than a band: at most a touch.
        const double a = lo.t + lo.g / -lo.slope;
        const double b = hi.t - hi.g / hi.slope;
        if (!(a <= b) || b - a < band) return none();
        const double step = a - lo.t;
        if (step <= tolerance) return passage(a, kNoInsidePoint);

        const double gap = hi.t - lo.t;
        Sample s = ray.sample(a);
        if (!s.finite()) return failed();
        if (s.g < 0.0) return passage(ray.refine(lo, s, tolerance), s.t);  // rounding put a just past the entry
        if (s.slope >= 0.0) return none();  // outside and past the minimum, yet not beyond the entry
        lo = s;
        const bool slow = step > kConvexSlowProgress * previousStep;
        previousStep = step;
        if (!slow) continue;

        // Newton from the right, then a bisection on the sign of g' (the minimum of g) if still slow.
        s = ray.sample(b);
        if (!s.finite()) return failed();
        if (s.g < 0.0) return passage(ray.refine(lo, s, tolerance), s.t);
        if (s.slope <= 0.0) return none();  // left of the minimum, outside, yet beyond the exit
        hi = s;
        if (hi.t - lo.t <= kConvexSlowProgress * gap) continue;
        s = ray.sample(0.5 * (lo.t + hi.t));
        if (!s.finite()) return failed();
        if (s.g < 0.0) return passage(ray.refine(lo, s, tolerance), s.t);
        if (s.slope == 0.0) return none();  // the minimum, and outside
        (s.slope < 0.0 ? lo : hi) = s;
    }
    return failed();
}

}  // namespace dropscope
