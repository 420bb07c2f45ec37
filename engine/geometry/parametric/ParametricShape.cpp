#include "geometry/parametric/ParametricShape.hpp"

#include "geometry/Tolerance.hpp"
#include "geometry/parametric/ParametricShapeTolerance.hpp"
#include "geometry/parametric/SurfaceIntegrals.hpp"

#include <array>
#include <cmath>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace dropscope {

namespace tp = tolerance::parametric;

namespace {

// Parity rays for locatePoint: fixed, far from the axes and from each other, so that a surface aligned with
// the axes (or a symmetric one) is unlikely to be grazed by two of them.
const std::array<Eigen::Vector3d, 6> kParityDirections = {
    Eigen::Vector3d(0.5773, 0.6134, 0.5390).normalized(),   Eigen::Vector3d(-0.7071, 0.2113, 0.6747).normalized(),
    Eigen::Vector3d(0.1623, -0.8830, 0.4404).normalized(),  Eigen::Vector3d(-0.3907, -0.4127, -0.8228).normalized(),
    Eigen::Vector3d(0.8660, -0.1951, -0.4603).normalized(), Eigen::Vector3d(-0.2449, 0.9063, -0.3443).normalized()};

// Seed 000 1.4.1: the range of x' = M_k r + r0_k. When row k of M has one non-zero entry m (a scaling, possibly
// with a permutation), it is m times the base's range of that coordinate; otherwise it is found anew
// (eqs. 1.64-1.66 through extremeRange).
ExtremeRange placedRange(const ParametricBase& base, const AffineTransform& transform, int k) {
    const Eigen::Vector3d row = transform.matrix().row(k).transpose();
    int nonZero = 0;
    int column = 0;
    for (int j = 0; j < 3; ++j) {
        if (row[j] != 0.0) {
            ++nonZero;
            column = j;
        }
    }
    ExtremeRange range;
    if (nonZero == 1) {
        const ExtremeRange& b = base.extremes()[static_cast<std::size_t>(column)];
        const double m = row[column];
        range = m > 0.0 ? ExtremeRange{m * b.min, m * b.max} : ExtremeRange{m * b.max, m * b.min};
    } else {
        range = extremeRange(base.surface(), row);
    }
    const double r0 = transform.translation()[k];
    return {range.min + r0, range.max + r0};
}

}  // namespace

struct ParametricShape::AreaCache {
    std::once_flag once;
    double value = 0.0;
};

ParametricShape::ParametricShape(std::shared_ptr<const ParametricBase> base, const AffineTransform& transform)
    : GeneralShape(transform), base_(std::move(base)), area_(std::make_shared<AreaCache>()) {
    if (!base_) throw std::invalid_argument("parametric base must not be null");
    Eigen::Vector3d lo, hi;
    for (int k = 0; k < 3; ++k) {
        const ExtremeRange range = placedRange(*base_, transform, k);
        lo[k] = range.min;
        hi[k] = range.max;
    }
    bounds_ = Eigen::AlignedBox3d(lo, hi);
    // Size: the base's characteristic length shrunk by the smallest singular value of M.
    const double size = surface().characteristicLength() * transform.classification().singularValues[2];
    band_ = tolerance::surfaceBand(size, largestCoordinate(bounds_));
}

double ParametricShape::surfaceArea() const {
    const TransformClass& c = transform().classification();
    if (c.isSimilarity) return c.uniformScale * c.uniformScale * base_->area();
    std::call_once(area_->once, [&] {
        area_->value =
            surfaceAreaIntegral(surface(), transform().matrix(), tp::kTransformedAreaRelative).value;  // 1.68
    });
    return area_->value;
}

double ParametricShape::volume() const { return std::abs(base_->signedVolume()) * std::abs(transform().determinant()); }

SurfaceProjection ParametricShape::closestPoint(const Point& p, double cutoff) const {
    return closestSurfacePoint(*base_, transform(), p, cutoff);
}

std::vector<RayCrossing> ParametricShape::crossings(const Point& p, const Direction& d, double sMin) const {
    if (!d) return {};
    return findRayCrossings(*base_, transform(), p, d.vector(), sMin, band_);
}

bool ParametricShape::withinBand(const Point& p) const {
    const Eigen::AlignedBox3d padded(bounds_.min().array() - band_, bounds_.max().array() + band_);
    if (!padded.contains(p)) return false;
    return closestPoint(p, band_).distance <= band_;  // seed 000 eqs. 1.74, 1.75
}

// Seed 000 1.4.5 assumes a convex surface and calls p inside when the rays along +w and -w both meet it. That
// fails for a torus (a point in the hole sees the tube both ways), so this counts crossings along one ray
// instead: an odd count is inside, for any closed surface. A ray that meets the surface near-tangentially or at a
// degenerate point of the parametrisation (where a crossing may be missed or counted twice) is replaced by the
// next direction; if every direction is doubtful the majority of their answers is taken.
PointLocation ParametricShape::locatePoint(const Point& p) const {
    if (!p.allFinite()) return PointLocation::Outside;
    if (withinBand(p)) return PointLocation::OnSurface;
    if (!bounds_.contains(p)) return PointLocation::Outside;
    int insideVotes = 0;
    int votes = 0;
    for (const Eigen::Vector3d& direction : kParityDirections) {
        const std::vector<RayCrossing> found = findRayCrossings(*base_, transform(), p, direction, 0.0, band_);
        const bool inside = found.size() % 2 == 1;
        bool clean = true;
        for (const RayCrossing& c : found)
            if (c.degenerate || std::abs(c.cosine) < tp::kParityMinCosine) clean = false;
        if (clean) return inside ? PointLocation::Inside : PointLocation::Outside;
        ++votes;
        if (inside) ++insideVotes;
    }
    return 2 * insideVotes > votes ? PointLocation::Inside : PointLocation::Outside;
}

// The distance semantics of Shape.hpp for any closed surface: from inside or outside, the nearest crossing ahead
// (NaN when there is none: the ray misses or only touches); from the surface band, the nearest crossing beyond the
// one at p itself (the far side when entering, a re-entry when leaving a non-convex shape), else 0.
double ParametricShape::distanceToSurface(const Point& p, const Direction& d) const {
    if (!d || !p.allFinite()) return std::numeric_limits<double>::quiet_NaN();
    const bool onSurface = withinBand(p);
    const double threshold = onSurface ? tp::kOwnCrossingBands * band_ : 0.0;
    const std::vector<RayCrossing> found = crossings(p, d, -tp::kOwnCrossingBands * band_);
    for (const RayCrossing& c : found)
        if (c.s > threshold) return c.s;
    return onSurface ? 0.0 : std::numeric_limits<double>::quiet_NaN();
}

Direction ParametricShape::normal(const Point& p) const {
    if (!p.allFinite()) return Direction::invalid();
    const double reach = tp::kNormalSearchBands * band_;
    const SurfaceProjection nearest = closestPoint(p, reach);
    if (!(nearest.distance <= reach)) return Direction::invalid();
    const Direction baseNormal = base_->outwardNormal(nearest.u, nearest.v);  // seed 000 eq. 1.71
    if (!baseNormal) return Direction::invalid();
    return transform().applyToNormal(baseNormal.vector());
}

std::unique_ptr<GeneralShape> ParametricShape::withTransform(const AffineTransform& transform) const {
    auto shape = std::make_unique<ParametricShape>(base_, transform);
    shape->setMediumId(mediumId());
    return shape;
}

}  // namespace dropscope
