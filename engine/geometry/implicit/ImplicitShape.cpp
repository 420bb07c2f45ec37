#include "geometry/implicit/ImplicitShape.hpp"

#include "geometry/Tolerance.hpp"
#include "geometry/implicit/ConvexBody.hpp"
#include "geometry/implicit/ConvexRaySearch.hpp"
#include "geometry/implicit/ImplicitTolerance.hpp"
#include "geometry/implicit/RayRootFinder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace dropscope {

using namespace tolerance::implicit;

std::shared_ptr<const ImplicitBase> makeImplicitBase(std::shared_ptr<const ImplicitFunction> function) {
    return std::make_shared<const ImplicitBase>(std::move(function));
}

ImplicitShape::ImplicitShape(std::shared_ptr<const ImplicitBase> base, const AffineTransform& transform)
    : GeneralShape(transform), base_(std::move(base)), derived_(std::make_shared<Derived>()) {
    if (!base_) throw std::invalid_argument("implicit base must not be null");
    convex_ = function().convexCenter().has_value();
    // The smallest feature scaled by the smallest singular value of M; coordinates from the placed bounds.
    const Eigen::AlignedBox3d placed = transform.applyToBox(base_->bounds());
    band_ = tolerance::surfaceBand(function().characteristicLength() * transform.classification().singularValues[2],
                                   largestCoordinate(placed));
}

double ImplicitShape::value(const Point& p) const { return function().value(transform().applyInverse(p)); }

Eigen::Vector3d ImplicitShape::gradient(const Point& p) const {
    return transform().inverseMatrix().transpose() * function().gradient(transform().applyInverse(p));
}

const std::array<double, 6>& ImplicitShape::extremes() const {
    std::call_once(derived_->extremesOnce, [this] {
        // max over the placed body of e_k . (M r + r0) = (M^T e_k) . r + r0_k, r in the base body.
        const Eigen::AlignedBox3d& bounds = base_->bounds();
        const double tol = kExtremeRelative * transform().applyToBox(bounds).diagonal().norm();
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d ell = transform().matrix().row(k).transpose();
            const double offset = transform().translation()[k];
            // The outward side of each certified interval, so that bounds() contains the shape.
            derived_->extremes[static_cast<std::size_t>(2 * k)] =
                offset - maximumOverBody(function(), bounds, -ell, tol).upper;
            derived_->extremes[static_cast<std::size_t>(2 * k + 1)] =
                offset + maximumOverBody(function(), bounds, ell, tol).upper;
        }
    });
    return derived_->extremes;
}

IntegralEstimate ImplicitShape::volumeEstimate() const {
    const double scale = std::abs(transform().determinant());
    const IntegralEstimate& base = base_->integrals().volume;
    return {base.value * scale, base.errorEstimate * scale};
}

IntegralEstimate ImplicitShape::areaEstimate() const {
    const TransformClass& c = transform().classification();
    if (c.isSimilarity) {
        const double scale = c.uniformScale * c.uniformScale;
        const IntegralEstimate& base = base_->integrals().area;
        return {base.value * scale, base.errorEstimate * scale};
    }
    std::call_once(derived_->areaOnce, [this] {
        if (const std::optional<Point> center = function().convexCenter()) {
            derived_->area = convexBodyIntegrals(function(), *center, base_->bounds(), transform(), base_->band(),
                                                 kConvexIntegralOrder)
                                 .area;
            return;
        }
        // Over the certified (outward) bounds, padded like the base's, so the ends of every line are outside.
        const Eigen::AlignedBox3d tight = bounds();
        const double padding = kBoundsPaddingRelative * tight.diagonal().norm();
        const Eigen::AlignedBox3d world(tight.min().array() - padding, tight.max().array() + padding);
        derived_->area = bodyIntegrals(function(), transform(), base_->bounds(), world, band_, kIntegralLines).area;
    });
    return derived_->area;
}

PointLocation ImplicitShape::locatePoint(const Point& p) const {
    if (!p.allFinite()) return PointLocation::Outside;
    const Point r = transform().applyInverse(p);
    const double f = function().value(r);
    if (std::isnan(f)) return PointLocation::Outside;
    // |f| / |grad f| <= band, written without the division (grad f may vanish deep inside).
    const double slope = (transform().inverseMatrix().transpose() * function().gradient(r)).norm();
    if (std::abs(f) <= band_ * slope) return PointLocation::OnSurface;
    return f < 0.0 ? PointLocation::Inside : PointLocation::Outside;
}

double ImplicitShape::distanceToSurface(const Point& p, const Direction& d) const {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    if (!d || !p.allFinite()) return kNaN;
    const PointLocation start = locatePoint(p);
    const Point origin = transform().applyInverse(p);
    const Eigen::Vector3d direction = transform().applyInverseToVector(d.vector());  // t stays the world distance
    const auto range = clipToBox(base_->bounds(), origin, direction);
    const double noCrossing = start == PointLocation::OnSurface ? 0.0 : kNaN;
    if (!range || range->second <= 0.0) return noCrossing;
    if (convex_) {
        if (const std::optional<double> t = convexDistance(start, origin, direction, *range)) return *t;
    }
    return lipschitzDistance(start, origin, direction, *range);
}

std::optional<double> ImplicitShape::convexDistance(PointLocation start, const Point& origin,
                                                    const Eigen::Vector3d& direction,
                                                    const std::pair<double, double>& range) const {
    // The same answers as lipschitzDistance, from the convexity of g(t) = f(origin + t direction): one
    // interval inside, so from outside the entry, from inside the exit, from the surface the far side's
    // exit when entering and 0 when leaving (no re-entry).
    using Status = ConvexRayResult::Status;
    const ImplicitFunction& f = function();
    const double tolerance = kRefineBands * band_;
    const double tEnd = range.second;  // g > 0 there: the box is padded
    const auto answer = [](const ConvexRayResult& r, double none) -> std::optional<double> {
        if (r.status == Status::Failed) return std::nullopt;
        return r.status == Status::Found ? r.t : none;
    };
    if (start == PointLocation::Outside) {
        return answer(convexEntry(f, origin, direction, std::max(0.0, range.first), tEnd, band_, tolerance),
                      std::numeric_limits<double>::quiet_NaN());
    }
    if (start == PointLocation::Inside) {
        const ConvexRayResult exit = convexExit(f, origin, direction, 0.0, tEnd, tolerance);
        if (exit.status != Status::Found) return std::nullopt;  // from inside there is an exit: rounding
        return exit.t;
    }

    // On the surface: g' >= grad f . direction >= 0 (a subgradient bounds the directional derivative)
    // means g never decreases again, so nothing lies ahead but the ray's own crossing.
    if (f.gradient(origin).dot(direction) >= 0.0) return 0.0;
    const double own = kSelfCrossingBands * band_;  // crossings up to here are the ray's own
    if (own >= tEnd) return 0.0;
    if (!(f.value(origin + own * direction) < 0.0)) {
        // Not inside yet (p lay just outside, the ray nearly tangent): the body may still lie ahead, and
        // count only if the ray passes through it.
        const ConvexRayResult entry = convexEntry(f, origin, direction, own, tEnd, band_, tolerance);
        if (entry.status != Status::Found) return answer(entry, 0.0);
    }
    return answer(convexExit(f, origin, direction, own, tEnd, tolerance), 0.0);
}

double ImplicitShape::lipschitzDistance(PointLocation start, const Point& origin, const Eigen::Vector3d& direction,
                                        const std::pair<double, double>& range) const {
    // Which crossing answers: from inside the exit, from outside the entry; from the surface, the exit
    // on the far side when the ray enters, a re-entry when it leaves (or is tangent), skipping the
    // crossing at p itself.
    const double noCrossing = start == PointLocation::OnSurface ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    bool wantEntering = start == PointLocation::Outside;
    double ownCrossing = -1.0;
    if (start == PointLocation::OnSurface) {
        wantEntering = function().gradient(origin).dot(direction) >= 0.0;
        ownCrossing = kSelfCrossingBands * band_;
    }
    RayRootFinder finder(function(), origin, direction, std::max(0.0, range.first), range.second, kMinStepBands * band_,
                         kRefineBands * band_);
    while (const auto crossing = finder.next()) {
        if (crossing->t <= ownCrossing || crossing->entering != wantEntering) continue;
        // An entry that is out again within the band is a grazing touch, not a hit.
        if (crossing->entering && !(finder.valueAt(crossing->t + band_) < 0.0)) continue;
        return crossing->t;
    }
    return noCrossing;
}

Direction ImplicitShape::normal(const Point& p) const {
    if (!p.allFinite()) return Direction::invalid();
    const Point r = transform().applyInverse(p);
    const Eigen::Vector3d g = transform().inverseMatrix().transpose() * function().gradient(r);
    if (!(std::abs(function().value(r)) <= kNormalBands * band_ * g.norm())) return Direction::invalid();
    return Direction(g);  // invalid when the gradient vanishes
}

std::unique_ptr<GeneralShape> ImplicitShape::withTransform(const AffineTransform& transform) const {
    auto shape = std::make_unique<ImplicitShape>(base_, transform);
    shape->setMediumId(mediumId());
    return shape;
}

}  // namespace dropscope
