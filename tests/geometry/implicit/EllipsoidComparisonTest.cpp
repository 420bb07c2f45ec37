// A superellipsoid with e1 = e2 = 1 is an ellipsoid: every answer of the implicit machinery is checked
// against the closed-form Ellipsoid class, under random placements M r + r0.
#include "ImplicitTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace dropscope::testing {
namespace {

constexpr int kPlacements = 6;
constexpr int kRaysPerPlacement = 600;

struct Pair {
    Ellipsoid reference;
    ImplicitShape shape;
};

Pair makePair(const std::shared_ptr<const ImplicitBase>& base, const Eigen::Vector3d& semiAxes, Rng& rng,
              bool similarity = false) {
    const AffineTransform t = randomPlacement(rng, similarity);
    return {placedEllipsoid(semiAxes, t), ImplicitShape(base, t)};
}

const Eigen::Vector3d kSemiAxes(1.0, 0.6, 0.35);

std::shared_ptr<const ImplicitBase> ellipsoidBase() {
    static const auto base = makeImplicitBase(makeSuperellipsoid(kSemiAxes, Eigen::Vector2d(1.0, 1.0)));
    return base;
}

void expectSameDistance(const Shape& reference, const Shape& shape, const Point& p, const Direction& d, double tol,
                        const std::string& where) {
    const double expected = reference.distanceToSurface(p, d);
    const double actual = shape.distanceToSurface(p, d);
    ASSERT_EQ(std::isnan(expected), std::isnan(actual)) << where << " expected " << expected << " got " << actual;
    if (!std::isnan(expected)) {
        ASSERT_NEAR(actual, expected, tol) << where;
    }
}

TEST(EllipsoidComparison, DistancesFromInsideOutsideAndOnTheSurfaceAgree) {
    int hits = 0;
    int misses = 0;
    for (int placement = 0; placement < kPlacements; ++placement) {
        Rng rng(100 + static_cast<unsigned>(placement));
        const Pair pair = makePair(ellipsoidBase(), kSemiAxes, rng);
        const Point center = pair.reference.center();
        const double size = pair.reference.semiAxes().maxCoeff();
        const double tol = 20.0 * pair.shape.surfaceBand();
        for (int i = 0; i < kRaysPerPlacement; ++i) {
            const std::string where = "placement " + std::to_string(placement) + " ray " + std::to_string(i);
            // Outside and inside (or near) points alike: a box of twice the size around the centre;
            // every other ray aimed near the centre, so that about half the rays hit.
            const Point p = randomPoint(rng, 2.0 * size, center);
            const Direction d = i % 2 == 0 ? randomDirection(rng) : Direction(randomPoint(rng, 0.3 * size, center) - p);
            ASSERT_EQ(pair.reference.locatePoint(p), pair.shape.locatePoint(p)) << where;
            expectSameDistance(pair.reference, pair.shape, p, d, tol, where + " (free point)");
            const double t = pair.reference.distanceToSurface(p, d);
            std::isnan(t) ? ++misses : ++hits;
            if (std::isnan(t)) continue;
            // From the hit point, in a random direction: the on-surface rules.
            const Point onSurface = p + t * d.vector();
            ASSERT_EQ(pair.shape.locatePoint(onSurface), PointLocation::OnSurface) << where;
            const Direction e = randomDirection(rng);
            expectSameDistance(pair.reference, pair.shape, onSurface, e, tol, where + " (surface point)");
            expectSameDistance(pair.reference, pair.shape, onSurface, d, tol, where + " (surface, same direction)");
            // Normals.
            const Direction expectedNormal = pair.reference.normal(onSurface);
            const Direction normal = pair.shape.normal(onSurface);
            ASSERT_TRUE(normal) << where;
            ASSERT_LT((normal.vector() - expectedNormal.vector()).norm(), 1e-8) << where;
        }
    }
    EXPECT_GT(hits, kPlacements * kRaysPerPlacement / 3);
    EXPECT_GT(misses, kPlacements * kRaysPerPlacement / 10);
}

TEST(EllipsoidComparison, GrazingRaysAreTouchesNotHits) {
    // A ray tangent to the placed ellipsoid, shifted by +-100 bands: outside it misses, inside it hits.
    Rng rng(7);
    for (int placement = 0; placement < 20; ++placement) {
        const Pair pair = makePair(ellipsoidBase(), kSemiAxes, rng);
        const Point inside = pair.reference.center();
        const Direction d = randomDirection(rng);
        const Point surfacePoint = inside + pair.reference.distanceToSurface(inside, d) * d.vector();
        const Direction n = pair.reference.normal(surfacePoint);
        const Direction tangent(n.vector().cross(randomDirection(rng).vector()));
        for (double shift : {-100.0, 100.0}) {
            const Point start = surfacePoint + shift * pair.shape.surfaceBand() * n.vector() - 3.0 * tangent.vector();
            expectSameDistance(pair.reference, pair.shape, start, tangent, 1e-6,
                               "placement " + std::to_string(placement) + " shift " + std::to_string(shift));
        }
    }
}

TEST(EllipsoidComparison, ExtremesAreCertifiedOutwardBounds) {
    for (int placement = 0; placement < kPlacements; ++placement) {
        Rng rng(200 + static_cast<unsigned>(placement));
        const Pair pair = makePair(ellipsoidBase(), kSemiAxes, rng);
        const double tol = tolerance::implicit::kExtremeRelative * 1.0001 *
                           pair.shape.transform().applyToBox(pair.shape.base()->bounds()).diagonal().norm();
        const double expected[6] = {pair.reference.xMin(), pair.reference.xMax(), pair.reference.yMin(),
                                    pair.reference.yMax(), pair.reference.zMin(), pair.reference.zMax()};
        const double actual[6] = {pair.shape.xMin(), pair.shape.xMax(), pair.shape.yMin(),
                                  pair.shape.yMax(), pair.shape.zMin(), pair.shape.zMax()};
        for (int k = 0; k < 6; ++k) {
            const double outward = (k % 2 == 0) ? expected[k] - actual[k] : actual[k] - expected[k];
            EXPECT_GE(outward, -1e-12) << "placement " << placement << " extreme " << k;
            EXPECT_LE(outward, tol) << "placement " << placement << " extreme " << k;
        }
    }
}

TEST(EllipsoidComparison, VolumeAndAreaWithinTheirErrorEstimates) {
    const double exactVolume = 4.0 / 3.0 * std::numbers::pi * kSemiAxes.prod();
    const double exactArea = ellipsoidSurfaceArea(kSemiAxes);
    const ImplicitShape base(ellipsoidBase(), AffineTransform());
    const IntegralEstimate volume = base.volumeEstimate();
    const IntegralEstimate area = base.areaEstimate();
    EXPECT_LE(std::abs(volume.value - exactVolume), volume.errorEstimate);
    EXPECT_LE(volume.errorEstimate, 1e-8 * exactVolume);
    EXPECT_LE(std::abs(area.value - exactArea), area.errorEstimate);
    EXPECT_LE(area.errorEstimate, 1e-8 * exactArea);
    std::printf("ellipsoid volume error %.3g (estimate %.3g), area error %.3g (estimate %.3g)\n",
                std::abs(volume.value - exactVolume) / exactVolume, volume.errorEstimate / exactVolume,
                std::abs(area.value - exactArea) / exactArea, area.errorEstimate / exactArea);

    // Placed: |det M| for the volume; K^2 for a similarity's area, the placed radial rule otherwise.
    Rng rng(300);
    for (int placement = 0; placement < 3; ++placement) {
        const bool similarity = placement == 0;
        const Pair pair = makePair(ellipsoidBase(), kSemiAxes, rng, similarity);
        const IntegralEstimate placedVolume = pair.shape.volumeEstimate();
        EXPECT_NEAR(placedVolume.value, pair.reference.volume(), placedVolume.errorEstimate) << placement;
        EXPECT_NEAR(placedVolume.value, volume.value * std::abs(pair.shape.transform().determinant()), 1e-12);
        const IntegralEstimate placedArea = pair.shape.areaEstimate();
        EXPECT_NEAR(placedArea.value, pair.reference.surfaceArea(), placedArea.errorEstimate) << placement;
        EXPECT_LE(placedArea.errorEstimate, 1e-8 * placedArea.value) << placement;
        if (similarity) {
            const double k = pair.shape.transform().classification().uniformScale;
            EXPECT_NEAR(placedArea.value, area.value * k * k, 1e-12 * placedArea.value);
        }
    }
}

}  // namespace
}  // namespace dropscope::testing
