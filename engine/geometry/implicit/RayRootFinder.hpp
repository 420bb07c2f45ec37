#pragma once

#include "geometry/implicit/ImplicitFunction.hpp"

#include <optional>
#include <vector>

namespace dropscope {

// One sign change of g(t) = f(origin + t direction).
struct RayCrossing {
    double t = 0.0;
    bool entering = false;                               // f goes from >= 0 to < 0: the ray enters the body
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  // grad f at the refined crossing
};

// Every crossing of g(t) = f(origin + t direction) for t in [tBegin, tEnd], in increasing t, one at a
// time. `direction` need not be unit: a placed shape passes the base-frame image M^-1 d of its unit
// world direction, so t is the world distance.
//
// Stepping: from t, no root lies closer than rho(t) = |g(t)| / L_d, L_d = f.lipschitzAlong(direction)
// (<= L |direction|), since |g(t') - g(t)| <= L_d |t' - t| < |g(t)| there. The next sample is
// t + max(rho(t), minStep), or an over-relaxed kOverRelaxation * rho(t) kept only when rho(t) + rho(t')
// still covers it. A sign change between samples is a bracket, refined by safeguarded Newton
// (bisection whenever Newton leaves the bracket) to refineTolerance.
//
// Guarantee: every sample interval [t, t'] is covered by the two root-free radii except for at most
// minStep, so no crossing is missed unless it lies within minStep of another one, i.e. unless the
// part of the body (or the gap between two parts) between two crossings is thinner than minStep along
// the ray. Such a pair is a touch (a graze) and reports nothing; the floor also makes a tangent ray
// terminate. A bracket holding three or more crossings within minStep reports one.
class RayRootFinder {
public:
    RayRootFinder(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction, double tBegin,
                  double tEnd, double minStep, double refineTolerance);

    // The next crossing, or nothing once tEnd is reached.
    std::optional<RayCrossing> next();

    // f at `t` along the ray.
    double valueAt(double t) const { return f_.value(origin_ + t * direction_); }

private:
    const ImplicitFunction& f_;
    Point origin_;
    Eigen::Vector3d direction_;
    double tEnd_;
    double minStep_;
    double refineTolerance_;
    double lipschitz_;
    double t_;
    double g_;
    bool relax_ = true;
};

// The crossing of g(t) = f(origin + t direction) inside the bracket [ta, tb], where ga = g(ta) and
// gb = g(tb) lie on opposite sides (g < 0 inside): safeguarded Newton from the secant point, bisection
// whenever Newton leaves the bracket, until a step or the bracket is below `tolerance`.
RayCrossing refineCrossing(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction, double ta,
                           double ga, double tb, double gb, double tolerance);

// All crossings in [tBegin, tEnd] (see RayRootFinder).
std::vector<RayCrossing> findRayCrossings(const ImplicitFunction& f, const Point& origin,
                                          const Eigen::Vector3d& direction, double tBegin, double tEnd, double minStep,
                                          double refineTolerance);

// The parameter interval [tEnter, tExit] of origin + t direction inside `box` (slab test), or nothing
// when the line misses it.
std::optional<std::pair<double, double>> clipToBox(const Eigen::AlignedBox3d& box, const Point& origin,
                                                   const Eigen::Vector3d& direction);

}  // namespace dropscope
