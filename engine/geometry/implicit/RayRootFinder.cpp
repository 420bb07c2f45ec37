#include "geometry/implicit/RayRootFinder.hpp"

#include "geometry/implicit/ImplicitTolerance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace dropscope {

namespace {

bool inside(double g) { return g < 0.0; }

}  // namespace

RayRootFinder::RayRootFinder(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction,
                             double tBegin, double tEnd, double minStep, double refineTolerance)
    : f_(f),
      origin_(origin),
      direction_(direction),
      tEnd_(tEnd),
      minStep_(minStep),
      refineTolerance_(refineTolerance),
      lipschitz_(f.lipschitzAlong(direction)),
      t_(tBegin),
      g_(valueAt(tBegin)) {}

std::optional<RayCrossing> RayRootFinder::next() {
    using tolerance::implicit::kOverRelaxation;
    while (t_ < tEnd_ && std::isfinite(g_)) {
        const double radius = std::abs(g_) / lipschitz_;  // no root within this distance of t_
        double tNext = std::numeric_limits<double>::quiet_NaN();
        double gNext = 0.0;
        if (relax_ && kOverRelaxation * radius > minStep_ && t_ + kOverRelaxation * radius < tEnd_) {
            // Try the longer step; keep it only when its root-free radius meets ours (up to minStep).
            const double tLong = t_ + kOverRelaxation * radius;
            const double gLong = valueAt(tLong);
            if (inside(gLong) == inside(g_) && radius + std::abs(gLong) / lipschitz_ + minStep_ >= tLong - t_) {
                tNext = tLong;
                gNext = gLong;
            } else {
                relax_ = false;  // back to the safe step, and to safe steps until one has been taken
            }
        } else {
            relax_ = true;
        }
        if (std::isnan(tNext)) {
            tNext = std::min(t_ + std::max(radius, minStep_), tEnd_);
            gNext = valueAt(tNext);
        }
        const double tPrevious = std::exchange(t_, tNext);
        const double gPrevious = std::exchange(g_, gNext);
        if (inside(gPrevious) != inside(gNext))
            return refineCrossing(f_, origin_, direction_, tPrevious, gPrevious, tNext, gNext, refineTolerance_);
    }
    return std::nullopt;
}

RayCrossing refineCrossing(const ImplicitFunction& f, const Point& origin, const Eigen::Vector3d& direction, double ta,
                           double ga, double tb, double gb, double tolerance) {
    const bool entering = !inside(ga);
    double t = ta + (tb - ta) * (ga / (ga - gb));
    if (!(t > ta && t < tb)) t = 0.5 * (ta + tb);
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (int iteration = 0; iteration < tolerance::implicit::kMaxRefineIterations; ++iteration) {
        const Point r = origin + t * direction;
        const double g = f.value(r);
        gradient = f.gradient(r);
        if (g == 0.0) break;
        if (inside(g) == inside(ga)) {
            ta = t;
            ga = g;
        } else {
            tb = t;
            gb = g;
        }
        if (tb - ta <= tolerance) {
            t = 0.5 * (ta + tb);
            break;
        }
        const double slope = gradient.dot(direction);
        const double newton = slope != 0.0 ? t - g / slope : std::numeric_limits<double>::quiet_NaN();
        if (newton > ta && newton < tb) {
            const bool converged = std::abs(newton - t) <= tolerance;
            t = newton;
            if (converged) break;
        } else {
            t = 0.5 * (ta + tb);
        }
    }
    return {t, entering, gradient};
}

std::vector<RayCrossing> findRayCrossings(const ImplicitFunction& f, const Point& origin,
                                          const Eigen::Vector3d& direction, double tBegin, double tEnd, double minStep,
                                          double refineTolerance) {
    RayRootFinder finder(f, origin, direction, tBegin, tEnd, minStep, refineTolerance);
    std::vector<RayCrossing> crossings;
    while (const std::optional<RayCrossing> crossing = finder.next()) crossings.push_back(*crossing);
    return crossings;
}

std::optional<std::pair<double, double>> clipToBox(const Eigen::AlignedBox3d& box, const Point& origin,
                                                   const Eigen::Vector3d& direction) {
    double tEnter = -std::numeric_limits<double>::infinity();
    double tExit = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (direction[i] == 0.0) {
            if (origin[i] < box.min()[i] || origin[i] > box.max()[i]) return std::nullopt;
            continue;
        }
        const double t1 = (box.min()[i] - origin[i]) / direction[i];
        const double t2 = (box.max()[i] - origin[i]) / direction[i];
        tEnter = std::max(tEnter, std::min(t1, t2));
        tExit = std::min(tExit, std::max(t1, t2));
    }
    if (!(tEnter <= tExit)) return std::nullopt;
    return std::make_pair(tEnter, tExit);
}

}  // namespace dropscope
