#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace dropscope {
namespace {

const Sphere kSphere(Point(1.0, 2.0, 3.0), 2.0);

TEST(Sphere, ExtremesAreaVolume) {
    EXPECT_EQ(kSphere.xMin(), -1.0);
    EXPECT_EQ(kSphere.xMax(), 3.0);
    EXPECT_EQ(kSphere.yMin(), 0.0);
    EXPECT_EQ(kSphere.zMax(), 5.0);
    EXPECT_DOUBLE_EQ(kSphere.surfaceArea(), 16.0 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(kSphere.volume(), 32.0 / 3.0 * std::numbers::pi);
}

TEST(Sphere, RejectsBadRadiusOrCenter) {
    EXPECT_THROW(Sphere(Point::Zero(), 0.0), std::invalid_argument);
    EXPECT_THROW(Sphere(Point::Zero(), -1.0), std::invalid_argument);
    EXPECT_THROW(Sphere(Point::Zero(), std::nan("")), std::invalid_argument);
    EXPECT_THROW(Sphere(Point(0, std::nan(""), 0), 1.0), std::invalid_argument);
}

TEST(Sphere, LocatesPoints) {
    EXPECT_TRUE(kSphere.encloses(Point(1.0, 2.0, 3.0)));
    EXPECT_TRUE(kSphere.surfaceContains(Point(3.0, 2.0, 3.0)));
    EXPECT_TRUE(kSphere.surfaceContains(Point(1.0 + std::sqrt(2.0), 2.0 + std::sqrt(2.0), 3.0)));
    EXPECT_FALSE(kSphere.encloses(Point(3.0, 2.0, 3.0)));
    EXPECT_FALSE(kSphere.surfaceContains(Point(3.1, 2.0, 3.0)));
    EXPECT_FALSE(kSphere.encloses(Point(3.1, 2.0, 3.0)));
}

TEST(Sphere, DistanceFromCenterIsTheRadius) {
    EXPECT_DOUBLE_EQ(kSphere.distanceToSurface(kSphere.center(), Direction(1, 1, 1)), 2.0);
}

TEST(Sphere, DistanceFromInsideOffCenter) {
    // from (1,2,3) + (1,0,0) along +y: half-chord sqrt(R^2 - 1)
    EXPECT_DOUBLE_EQ(kSphere.distanceToSurface(Point(2.0, 2.0, 3.0), Direction(0, 1, 0)), std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(kSphere.distanceToSurface(Point(2.0, 2.0, 3.0), Direction(-1, 0, 0)), 3.0);
}

TEST(Sphere, DistanceFromOutside) {
    EXPECT_DOUBLE_EQ(kSphere.distanceToSurface(Point(1.0, 2.0, -7.0), Direction(0, 0, 1)), 8.0);
    // offset by h = 1 from the axis: near root at 10 - sqrt(R^2 - h^2)
    EXPECT_NEAR(kSphere.distanceToSurface(Point(2.0, 2.0, -7.0), Direction(0, 0, 1)), 10.0 - std::sqrt(3.0), 1e-14);
}

TEST(Sphere, MissesAndMovingAwayAreNaN) {
    EXPECT_TRUE(std::isnan(kSphere.distanceToSurface(Point(4.0, 2.0, -7.0), Direction(0, 0, 1))));
    EXPECT_TRUE(std::isnan(kSphere.distanceToSurface(Point(1.0, 2.0, -7.0), Direction(0, 0, -1))));
}

TEST(Sphere, TangentRayOnlyTouches) {
    EXPECT_TRUE(std::isnan(kSphere.distanceToSurface(Point(3.0, 2.0, -7.0), Direction(0, 0, 1))));
}

TEST(Sphere, OnSurfaceLeavingIsZeroEnteringIsTheChord) {
    const Point top(1.0, 2.0, 5.0);
    EXPECT_EQ(kSphere.distanceToSurface(top, Direction(0, 0, 1)), 0.0);
    EXPECT_EQ(kSphere.distanceToSurface(top, Direction(1, 0, 0)), 0.0);  // tangent
    EXPECT_DOUBLE_EQ(kSphere.distanceToSurface(top, Direction(0, 0, -1)), 4.0);
    // entering at 60 degrees from the inward normal: chord 2 R cos(60 deg)
    const Direction oblique(std::sin(std::numbers::pi / 3), 0.0, -std::cos(std::numbers::pi / 3));
    EXPECT_NEAR(kSphere.distanceToSurface(top, oblique), 2.0, 1e-14);
}

TEST(Sphere, FarAwayOriginKeepsRelativeAccuracy) {
    // a 1 um droplet seen from 1 m: B^2 - C would lose every digit; the stable form keeps them.
    const Sphere droplet(Point(0.0, 0.0, 0.0), 1e-6);
    const double h = 0.6e-6;
    const double s = droplet.distanceToSurface(Point(h, 0.0, -1.0), Direction(0, 0, 1));
    EXPECT_NEAR(s, 1.0 - 0.8e-6, 1e-15);
    const Point hit = Point(h, 0.0, -1.0) + s * Eigen::Vector3d(0, 0, 1);
    EXPECT_TRUE(droplet.surfaceContains(hit));
}

TEST(Sphere, NormalIsRadialUnit) {
    const Direction n = kSphere.normal(Point(1.0 + std::sqrt(2.0), 2.0, 3.0 + std::sqrt(2.0)));
    ASSERT_TRUE(n);
    EXPECT_NEAR(n.x(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(n.y(), 0.0, 1e-15);
    EXPECT_NEAR(n.z(), std::sqrt(0.5), 1e-15);
    EXPECT_FALSE(kSphere.normal(Point(1.0, 2.0, 3.0)));
}

TEST(Sphere, InvalidDirectionGivesNaN) {
    EXPECT_TRUE(std::isnan(kSphere.distanceToSurface(Point(1.0, 2.0, 3.0), Direction(0, 0, 0))));
}

TEST(Sphere, Prints) {
    std::ostringstream os;
    os << kSphere;
    EXPECT_EQ(os.str(), "Sphere(center=(1, 2, 3), radius=2)");
}

}  // namespace
}  // namespace dropscope
