#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {
namespace {

using testing::Rng;

TEST(Ellipsoid, AxisAlignedExtremesAndVolume) {
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(1, 2, 3), Eigen::Vector3d(3, 2, 1));
    EXPECT_NEAR(e.xMin(), -2.0, 1e-14);
    EXPECT_NEAR(e.xMax(), 4.0, 1e-14);
    EXPECT_NEAR(e.yMin(), 0.0, 1e-14);
    EXPECT_NEAR(e.yMax(), 4.0, 1e-14);
    EXPECT_NEAR(e.zMin(), 2.0, 1e-14);
    EXPECT_NEAR(e.zMax(), 4.0, 1e-14);
    EXPECT_NEAR(e.volume(), 4.0 / 3.0 * std::numbers::pi * 6.0, 1e-13);
    EXPECT_NEAR(e.semiAxes().x(), 3.0, 1e-14);
    EXPECT_NEAR(e.semiAxes().z(), 1.0, 1e-14);
}

TEST(Ellipsoid, RotatedExtremesFollowSeedEq127) {
    // a = 1.5 along x, b = 1 along y, rotated 30 degrees about z:
    // x half-extent sqrt(a^2 cos^2 + b^2 sin^2), y half-extent sqrt(a^2 sin^2 + b^2 cos^2)
    const double angle = std::numbers::pi / 6;
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(3, 0, 0), Eigen::Vector3d(1.5, 1.0, 0.5),
                                                rotationAboutAxis(Direction(0, 0, 1), angle));
    const double c = std::cos(angle), s = std::sin(angle);
    EXPECT_NEAR(e.xMax() - 3.0, std::sqrt(2.25 * c * c + s * s), 1e-14);
    EXPECT_NEAR(e.yMax(), std::sqrt(2.25 * s * s + c * c), 1e-14);
    EXPECT_NEAR(e.zMax(), 0.5, 1e-14);
    EXPECT_NEAR(3.0 - e.xMin(), e.xMax() - 3.0, 1e-14);
}

TEST(Ellipsoid, ExtremePointsLieOnTheSurfaceForRandomRotations) {
    for (int i = 0; i < 200; ++i) {
        SCOPED_TRACE(i);
        Rng rng(static_cast<unsigned>(i));
        const Ellipsoid e = testing::randomEllipsoid(rng, Point::Zero(), 2.0);
        // seed eq. 1.23: the maximiser of x is r0 + M^{-1} i / sqrt(i . M^{-1} i)
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Vector3d column = e.inverseMatrix().col(axis);
            const Point extreme = e.center() + column / std::sqrt(column[axis]);
            EXPECT_TRUE(e.surfaceContains(extreme));
            const double expected = axis == 0 ? e.xMax() : axis == 1 ? e.yMax() : e.zMax();
            EXPECT_NEAR(extreme[axis], expected, 1e-12);
        }
    }
}

TEST(Ellipsoid, FromMatrixRecoversSemiAxes) {
    Eigen::Matrix3d m = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
    const Ellipsoid e = Ellipsoid::fromMatrix(Point(0, 3, 0), m);
    EXPECT_NEAR(e.semiAxes()[0], 1.0, 1e-15);
    EXPECT_NEAR(e.semiAxes()[1], 1.0 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(e.semiAxes()[2], 1.0 / std::sqrt(3.0), 1e-15);
    EXPECT_TRUE((e.matrix() * e.inverseMatrix()).isIdentity(1e-14));
    EXPECT_NEAR(e.yMax(), 3.0 + 1.0 / std::sqrt(2.0), 1e-15);
}

TEST(Ellipsoid, RejectsNonSpdNonSymmetricAndBadAxes) {
    Eigen::Matrix3d indefinite = Eigen::Vector3d(1.0, -2.0, 3.0).asDiagonal();
    EXPECT_THROW(Ellipsoid::fromMatrix(Point::Zero(), indefinite), std::invalid_argument);
    Eigen::Matrix3d singular = Eigen::Vector3d(1.0, 0.0, 3.0).asDiagonal();
    EXPECT_THROW(Ellipsoid::fromMatrix(Point::Zero(), singular), std::invalid_argument);
    Eigen::Matrix3d skew = Eigen::Matrix3d::Identity();
    skew(0, 1) = 0.1;
    EXPECT_THROW(Ellipsoid::fromMatrix(Point::Zero(), skew), std::invalid_argument);
    EXPECT_THROW(Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(1, 0, 1)), std::invalid_argument);
    EXPECT_THROW(Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(1, 1, 1), 2.0 * Eigen::Matrix3d::Identity()),
                 std::invalid_argument);
    EXPECT_THROW(Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(1e7, 1, 1)), std::invalid_argument);
}

TEST(Ellipsoid, DistanceAlongPrincipalAxes) {
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(1, 1, 1), Eigen::Vector3d(3, 2, 1));
    EXPECT_NEAR(e.distanceToSurface(Point(1, 1, 1), Direction(1, 0, 0)), 3.0, 1e-14);
    EXPECT_NEAR(e.distanceToSurface(Point(1, 1, 1), Direction(0, -1, 0)), 2.0, 1e-14);
    EXPECT_NEAR(e.distanceToSurface(Point(1, 1, -9), Direction(0, 0, 1)), 9.0, 1e-14);
    EXPECT_TRUE(std::isnan(e.distanceToSurface(Point(1, 4, -9), Direction(0, 0, 1))));
}

TEST(Ellipsoid, DistanceOnSurfaceFollowsTheSeedRules) {
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(3, 2, 1));
    EXPECT_EQ(e.distanceToSurface(Point(3, 0, 0), Direction(1, 0, 0)), 0.0);
    EXPECT_EQ(e.distanceToSurface(Point(3, 0, 0), Direction(0, 1, 0)), 0.0);  // tangent
    EXPECT_NEAR(e.distanceToSurface(Point(3, 0, 0), Direction(-1, 0, 0)), 6.0, 1e-14);
}

TEST(Ellipsoid, NormalMatchesSeedEq163ForAxisAligned) {
    const double a = 3, b = 2, c = 1;
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(a, b, c));
    const double theta = 0.7, phi = 1.1;
    const Point p(a * std::sin(theta) * std::cos(phi), b * std::sin(theta) * std::sin(phi), c * std::cos(theta));
    const Eigen::Vector3d expected = Eigen::Vector3d(p.x() / (a * a), p.y() / (b * b), p.z() / (c * c)).normalized();
    const Direction n = e.normal(p);
    ASSERT_TRUE(n);
    EXPECT_TRUE(n.vector().isApprox(expected, 1e-14));
    EXPECT_FALSE(e.normal(Point(0.1, 0.1, 0.1)));
}

TEST(Ellipsoid, EqualAxesBehaveLikeASphere) {
    for (int i = 0; i < 500; ++i) {
        SCOPED_TRACE(i);
        Rng rng(static_cast<unsigned>(i));
        const double r = testing::uniform(rng, 0.1, 2.0);
        const Point c = testing::randomPoint(rng, 3.0);
        const Sphere sphere(c, r);
        const Ellipsoid ellipsoid = Ellipsoid::fromSemiAxes(c, Eigen::Vector3d(r, r, r), testing::randomRotation(rng));
        EXPECT_NEAR(ellipsoid.surfaceArea(), sphere.surfaceArea(), 1e-13 * sphere.surfaceArea());
        const Point p = testing::randomPoint(rng, 3.0, c);
        const Direction d = testing::randomDirection(rng);
        const double expected = sphere.distanceToSurface(p, d);
        const double actual = ellipsoid.distanceToSurface(p, d);
        EXPECT_EQ(std::isnan(expected), std::isnan(actual));
        if (!std::isnan(expected)) {
            EXPECT_NEAR(actual, expected, 1e-12 * (1.0 + expected));
        }
    }
}

}  // namespace
}  // namespace dropscope
