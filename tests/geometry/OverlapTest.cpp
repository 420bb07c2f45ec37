#include "geometry/Box.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/Sphere.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope {
namespace {

const Box kUnit(Point(0, 0, 0), Point(1, 1, 1));

TEST(BoxOverlap, SharedVolumeOverlapsTouchingDoesNot) {
    EXPECT_TRUE(kUnit.overlaps(Box(Point(0.5, 0.5, 0.5), Point(2, 2, 2))));
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 0, 0), Point(2, 1, 1))));                   // shared face
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 1, 0), Point(2, 2, 1))));                   // shared edge
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 1, 1), Point(2, 2, 2))));                   // shared vertex
    EXPECT_FALSE(kUnit.overlaps(Box(Point(0.5, 1.5, 0), Point(2, 2, 1))));               // apart along y only
    EXPECT_TRUE(kUnit.overlaps(Box(Point(0.25, 0.25, 0.25), Point(0.75, 0.75, 0.75))));  // nested
    EXPECT_TRUE(kUnit.overlaps(kUnit));
}

TEST(SphereOverlap, SeedEq16CentersCloserThanTheRadii) {
    const Sphere a(Point(0, 0, 0), 1.0);
    EXPECT_TRUE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.6)));
    EXPECT_FALSE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.5)));  // touching
    EXPECT_TRUE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.5 + 1e-6)));
    EXPECT_FALSE(a.overlaps(Sphere(Point(0, 3, 0), 1.0)));
    EXPECT_TRUE(a.overlaps(Sphere(Point(0.1, 0, 0), 0.2)));  // nested
}

TEST(SphereBoxOverlap, SeedEqs17And18ClosestPoint) {
    EXPECT_TRUE(Sphere(Point(0.5, 0.5, 0.5), 0.1).overlaps(kUnit));   // inside
    EXPECT_TRUE(Sphere(Point(0.5, 0.5, 0.5), 5.0).overlaps(kUnit));   // box inside sphere
    EXPECT_TRUE(Sphere(Point(1.5, 0.5, 0.5), 0.6).overlaps(kUnit));   // through a face
    EXPECT_FALSE(Sphere(Point(1.5, 0.5, 0.5), 0.5).overlaps(kUnit));  // touching a face
    // near a vertex the closest point is the corner (1, 1, 1), sqrt(3)/2 away
    const double toCorner = std::sqrt(3.0) * 0.5;
    EXPECT_TRUE(Sphere(Point(1.5, 1.5, 1.5), toCorner + 1e-6).overlaps(kUnit));
    EXPECT_FALSE(Sphere(Point(1.5, 1.5, 1.5), toCorner - 1e-6).overlaps(kUnit));
    EXPECT_TRUE(kUnit.overlaps(Sphere(Point(1.5, 1.5, 1.5), toCorner + 1e-6)));  // symmetric
}

// Every pair of kinds: the verdict is symmetric and agrees with Monte Carlo samples of the shared
// bounding region. A sample strictly inside both proves an overlap; an overlap almost always shows
// one (it can escape the samples only when the shared volume is a tiny sliver).
TEST(ShapeOverlap, SymmetricAndAgreesWithSampledIntersection) {
    constexpr int kPairs = 900;
    constexpr int kSamples = 4000;
    int overlapping = 0;
    int witnessed = 0;
    for (int i = 0; i < kPairs; ++i) {
        SCOPED_TRACE(::testing::Message() << "pair " << i);
        testing::Rng rng(static_cast<unsigned>(i));
        const auto a = testing::randomShape(rng, i, Point::Zero(), 1.0);
        const auto b = testing::randomShape(rng, i / 3, Point(0.8, 0.0, 0.0), 1.0);
        const bool verdict = a->overlaps(*b);
        ASSERT_EQ(verdict, b->overlaps(*a));
        const Point lower = Point(a->xMin(), a->yMin(), a->zMin()).cwiseMax(Point(b->xMin(), b->yMin(), b->zMin()));
        const Point upper = Point(a->xMax(), a->yMax(), a->zMax()).cwiseMin(Point(b->xMax(), b->yMax(), b->zMax()));
        bool witness = false;
        if ((lower.array() < upper.array()).all()) {
            for (int k = 0; k < kSamples && !witness; ++k) {
                const Point p(testing::uniform(rng, lower.x(), upper.x()), testing::uniform(rng, lower.y(), upper.y()),
                              testing::uniform(rng, lower.z(), upper.z()));
                witness = a->encloses(p) && b->encloses(p);
            }
        }
        if (witness) {
            EXPECT_TRUE(verdict) << *a << " / " << *b;
        }
        overlapping += verdict ? 1 : 0;
        witnessed += witness ? 1 : 0;
    }
    EXPECT_GT(overlapping, kPairs / 4);
    EXPECT_GE(witnessed, overlapping * 97 / 100);
}

}  // namespace
}  // namespace dropscope
