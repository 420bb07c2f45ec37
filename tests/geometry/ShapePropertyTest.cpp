// Random property tests shared by every shape: the guarantees the tracer relies on
// (docs/geometry.md, "What the tracer can rely on").
#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope {
namespace {

using testing::Rng;

constexpr int kCases = 3000;

// Droplets near the origin, and the same far from it where coordinate rounding dominates the band.
struct Placement {
    Point around;
    double size;
};
const Placement kPlacements[] = {{Point(0.0, 0.0, 0.0), 1.0}, {Point(1e3, -2e3, 5e2), 1e-3}};

// A ray from outside the shape's bounds aimed at a random point of its bounding box.
std::pair<Point, Direction> rayTowards(Rng& rng, const Shape& shape) {
    const double reach = testing::boundsDiagonal(shape);
    const Point target = testing::randomPoint(rng, 0.5 * reach, testing::boundsCenter(shape));
    const Direction d = testing::randomDirection(rng);
    return {target - 2.0 * reach * d.vector(), d};
}

class ShapeProperties : public ::testing::TestWithParam<int> {};

TEST_P(ShapeProperties, HitFromOutsideLandsOnTheSurfaceAndDoesNotRehit) {
    const Placement placement = kPlacements[GetParam()];
    int hits = 0;
    for (int i = 0; i < kCases; ++i) {
        SCOPED_TRACE(::testing::Message() << "case " << i);
        Rng rng(static_cast<unsigned>(i));
        const auto shape = testing::randomShape(rng, i, placement.around, placement.size);
        const auto [origin, d] = rayTowards(rng, *shape);
        ASSERT_EQ(shape->locatePoint(origin), PointLocation::Outside);
        const double s = shape->distanceToSurface(origin, d);
        if (std::isnan(s)) continue;
        ++hits;
        ASSERT_GT(s, 0.0);
        const Point hit = origin + s * d.vector();
        ASSERT_TRUE(shape->surfaceContains(hit)) << *shape;
        const Direction n = shape->normal(hit);
        ASSERT_TRUE(n) << "no normal at " << hit.transpose();
        EXPECT_NEAR(n.vector().norm(), 1.0, 1e-14);
        EXPECT_LT(n.dot(d.vector()), 0.0) << "entering against the outward normal";
        // Continuing from the hit point crosses the whole shape: never a spurious ~0 root.
        const double chord = shape->distanceToSurface(hit, d);
        EXPECT_GT(chord, 1e3 * shape->surfaceBand());
        const Point exit = hit + chord * d.vector();
        EXPECT_TRUE(shape->surfaceContains(exit));
        EXPECT_TRUE(shape->encloses(hit + 0.5 * chord * d.vector()));
        // At the exit the ray leaves: exactly 0 (the seed's rule), and the normal faces along d.
        EXPECT_EQ(shape->distanceToSurface(exit, d), 0.0);
        const Direction exitNormal = shape->normal(exit);
        ASSERT_TRUE(exitNormal);
        EXPECT_GT(exitNormal.dot(d.vector()), 0.0);
    }
    EXPECT_GT(hits, kCases / 4);
}

TEST_P(ShapeProperties, FromInsideBothWaysReachTheSurface) {
    const Placement placement = kPlacements[GetParam()];
    for (int i = 0; i < kCases; ++i) {
        SCOPED_TRACE(::testing::Message() << "case " << i);
        Rng rng(static_cast<unsigned>(i));
        const auto shape = testing::randomShape(rng, i, placement.around, placement.size);
        const Point p = testing::randomPoint(rng, 0.5 * testing::boundsDiagonal(*shape), testing::boundsCenter(*shape));
        if (!shape->encloses(p)) continue;
        const Direction d = testing::randomDirection(rng);
        for (const Direction& way : {d, -d}) {
            const double s = shape->distanceToSurface(p, way);
            ASSERT_GT(s, 0.0);
            ASSERT_TRUE(std::isfinite(s));
            const Point hit = p + s * way.vector();
            EXPECT_TRUE(shape->surfaceContains(hit));
            EXPECT_EQ(shape->distanceToSurface(hit, way), 0.0);                              // leaving
            EXPECT_GT(shape->distanceToSurface(hit, -way), s - 1e3 * shape->surfaceBand());  // re-entering crosses back
        }
    }
}

// Convexity: from a point outside, at most one of the two directions along a line enters.
TEST_P(ShapeProperties, OutsidePointsSeeTheShapeOnOneSideAtMost) {
    const Placement placement = kPlacements[GetParam()];
    for (int i = 0; i < kCases; ++i) {
        SCOPED_TRACE(::testing::Message() << "case " << i);
        Rng rng(static_cast<unsigned>(i));
        const auto shape = testing::randomShape(rng, i, placement.around, placement.size);
        const Point p = testing::randomPoint(rng, testing::boundsDiagonal(*shape), testing::boundsCenter(*shape));
        if (shape->locatePoint(p) != PointLocation::Outside) continue;
        const Direction d = testing::randomDirection(rng);
        const bool forward = !std::isnan(shape->distanceToSurface(p, d));
        const bool backward = !std::isnan(shape->distanceToSurface(p, -d));
        EXPECT_FALSE(forward && backward);
    }
}

// Stepping off a surface point along the normal leaves the shape; against it enters.
TEST_P(ShapeProperties, NormalPointsOutward) {
    const Placement placement = kPlacements[GetParam()];
    for (int i = 0; i < kCases; ++i) {
        SCOPED_TRACE(::testing::Message() << "case " << i);
        Rng rng(static_cast<unsigned>(i));
        const auto shape = testing::randomShape(rng, i, placement.around, placement.size);
        const Point inside = testing::boundsCenter(*shape);
        if (!shape->encloses(inside)) continue;
        const Direction d = testing::randomDirection(rng);
        const Point hit = inside + shape->distanceToSurface(inside, d) * d.vector();
        const Direction n = shape->normal(hit);
        if (!n) continue;  // a box edge or vertex: measure zero, but allowed
        const double step = 1e-6 * placement.size;
        EXPECT_EQ(shape->locatePoint(hit + step * n.vector()), PointLocation::Outside);
        EXPECT_EQ(shape->locatePoint(hit - step * n.vector()), PointLocation::Inside);
    }
}

INSTANTIATE_TEST_SUITE_P(NearAndFar, ShapeProperties, ::testing::Values(0, 1));

}  // namespace
}  // namespace dropscope
