#include "geometry/Box.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope {
namespace {

const Box kUnit(Point(0, 0, 0), Point(1, 1, 1));

TEST(BoxOverlap, SharedVolumeOverlapsTouchingDoesNot) {
    EXPECT_TRUE(kUnit.overlaps(Box(Point(0.5, 0.5, 0.5), Point(2, 2, 2))));
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 0, 0), Point(2, 1, 1))));    // shared face
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 1, 0), Point(2, 2, 1))));    // shared edge
    EXPECT_FALSE(kUnit.overlaps(Box(Point(1, 1, 1), Point(2, 2, 2))));    // shared vertex
    EXPECT_FALSE(kUnit.overlaps(Box(Point(0.5, 1.5, 0), Point(2, 2, 1)))); // apart along y only
    EXPECT_TRUE(kUnit.overlaps(Box(Point(0.25, 0.25, 0.25), Point(0.75, 0.75, 0.75))));  // nested
    EXPECT_TRUE(kUnit.overlaps(kUnit));
}

TEST(SphereOverlap, SeedEq16CentresCloserThanTheRadii) {
    const Sphere a(Point(0, 0, 0), 1.0);
    EXPECT_TRUE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.6)));
    EXPECT_FALSE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.5)));  // touching
    EXPECT_TRUE(a.overlaps(Sphere(Point(1.5, 0, 0), 0.5 + 1e-6)));
    EXPECT_FALSE(a.overlaps(Sphere(Point(0, 3, 0), 1.0)));
    EXPECT_TRUE(a.overlaps(Sphere(Point(0.1, 0, 0), 0.2)));  // nested
}

TEST(SphereBoxOverlap, SeedEqs17And18ClosestPoint) {
    EXPECT_TRUE(Sphere(Point(0.5, 0.5, 0.5), 0.1).overlaps(kUnit));  // inside
    EXPECT_TRUE(Sphere(Point(0.5, 0.5, 0.5), 5.0).overlaps(kUnit));  // box inside sphere
    EXPECT_TRUE(Sphere(Point(1.5, 0.5, 0.5), 0.6).overlaps(kUnit));  // through a face
    EXPECT_FALSE(Sphere(Point(1.5, 0.5, 0.5), 0.5).overlaps(kUnit)); // touching a face
    // near a vertex the closest point is the corner (1, 1, 1), sqrt(3)/2 away
    const double toCorner = std::sqrt(3.0) * 0.5;
    EXPECT_TRUE(Sphere(Point(1.5, 1.5, 1.5), toCorner + 1e-6).overlaps(kUnit));
    EXPECT_FALSE(Sphere(Point(1.5, 1.5, 1.5), toCorner - 1e-6).overlaps(kUnit));
    EXPECT_TRUE(kUnit.overlaps(Sphere(Point(1.5, 1.5, 1.5), toCorner + 1e-6)));  // symmetric
}

}  // namespace
}  // namespace dropscope
