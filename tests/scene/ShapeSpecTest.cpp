// ShapeSpec: makeShape builds what the fields say, describeShape gives them back.
#include "scene/ShapeSpec.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace dropscope {
namespace {

// The matrix rebuilt from an ellipsoid's description carries the eigensolver's and the rotation's
// rounding: a few ulps of its largest entry.
constexpr double kMatrixRelative = 1e-12;
// Semi-axes recovered as 1/sqrt of the eigenvalues of M, and rotations compared entry by entry: a few ulps.
constexpr double kRecoveredRelative = 1e-13;

std::string refusalOf(const ShapeSpec& spec) {
    try {
        makeShape(spec);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "accepted";
}

double matrixDifference(const Shape& a, const Shape& b) {
    const auto& m = static_cast<const Ellipsoid&>(a).matrix();
    return (m - static_cast<const Ellipsoid&>(b).matrix()).cwiseAbs().maxCoeff() / m.cwiseAbs().maxCoeff();
}

TEST(ShapeSpec, SphereRoundTripsExactly) {
    ShapeSpec spec;
    spec.center = Point(0.1, -2.3, 1e6);
    spec.radius = 0.37;
    spec.medium = 4;
    const auto shape = makeShape(spec);
    ASSERT_EQ(shape->kind(), ShapeKind::Sphere);
    EXPECT_EQ(shape->mediumId(), 4u);
    const ShapeSpec back = describeShape(*shape);
    EXPECT_EQ(back.kind, ShapeKind::Sphere);
    EXPECT_EQ(back.center, spec.center);
    EXPECT_EQ(back.radius, spec.radius);
    EXPECT_EQ(back.medium, 4u);
}

TEST(ShapeSpec, BoxRoundTripsExactlyWithItsCenter) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Box;
    spec.boxMin = Point(-1.5, 0.1, 2.0);
    spec.boxMax = Point(0.3, 0.7, 9.0);
    spec.medium = 1;
    const auto shape = makeShape(spec);
    const auto& box = static_cast<const Box&>(*shape);
    EXPECT_EQ(box.lower(), spec.boxMin);
    EXPECT_EQ(box.upper(), spec.boxMax);
    const ShapeSpec back = describeShape(*shape);
    EXPECT_EQ(back.kind, ShapeKind::Box);
    EXPECT_EQ(back.boxMin, spec.boxMin);
    EXPECT_EQ(back.boxMax, spec.boxMax);
    EXPECT_EQ(back.center, box.center());
    EXPECT_EQ(back.medium, 1u);
}

TEST(ShapeSpec, WithCenterMovesABoxAndKeepsItsEdges) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Box;
    spec.boxMin = Point(0.0, 0.0, 0.0);
    spec.boxMax = Point(2.0, 4.0, 6.0);
    const ShapeSpec moved = withCenter(spec, Point(10.0, 10.0, 10.0));
    EXPECT_EQ(moved.boxMin, Point(9.0, 8.0, 7.0));
    EXPECT_EQ(moved.boxMax, Point(11.0, 12.0, 13.0));
    EXPECT_EQ(moved.center, Point(10.0, 10.0, 10.0));
    ShapeSpec sphere;
    EXPECT_EQ(withCenter(sphere, Point(1.0, 2.0, 3.0)).center, Point(1.0, 2.0, 3.0));
}

TEST(ShapeSpec, UnrotatedEllipsoidIsDescribedWithoutRotation) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Ellipsoid;
    spec.center = Point(1.0, 2.0, 3.0);
    spec.semiAxes = Eigen::Vector3d(0.5, 1.0, 1.5);  // not longest first: the frame keeps x, y, z
    const ShapeSpec back = describeShape(*makeShape(spec));
    EXPECT_EQ(back.kind, ShapeKind::Ellipsoid);
    EXPECT_EQ(back.center, spec.center);
    EXPECT_EQ(back.rotationAngleDeg, 0.0);
    EXPECT_EQ(back.rotationAxis, Eigen::Vector3d(0.0, 0.0, 1.0));
    EXPECT_LE((back.semiAxes - spec.semiAxes).cwiseAbs().maxCoeff(), kRecoveredRelative * 1.5);
}

TEST(ShapeSpec, SmallAngledEllipsoidComesBackWithItsOwnRotation) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Ellipsoid;
    spec.semiAxes = Eigen::Vector3d(1.5, 1.0, 0.5);
    spec.rotationAxis = Eigen::Vector3d(0.0, 0.0, 2.0);
    spec.rotationAngleDeg = 30.0;
    const ShapeSpec back = describeShape(*makeShape(spec));
    EXPECT_NEAR(back.rotationAngleDeg, 30.0, kRecoveredRelative * 180.0);
    EXPECT_LE((back.rotationAxis - Eigen::Vector3d(0.0, 0.0, 1.0)).cwiseAbs().maxCoeff(), kRecoveredRelative);
    EXPECT_LE((back.semiAxes - spec.semiAxes).cwiseAbs().maxCoeff(), kRecoveredRelative * 1.5);
}

TEST(ShapeSpec, RandomEllipsoidsRoundTripTheirMatrix) {
    for (int i = 0; i < 500; ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        testing::Rng rng(static_cast<std::uint64_t>(i));
        ShapeSpec spec;
        spec.kind = ShapeKind::Ellipsoid;
        spec.center = testing::randomPoint(rng, 100.0);
        const auto length = [&] { return std::pow(10.0, testing::uniform(rng, -2, 2)); };
        spec.semiAxes = Eigen::Vector3d(length(), length(), length());
        if (i % 5 == 0) spec.semiAxes.y() = spec.semiAxes.x();  // spheroids: the axes are not unique
        spec.rotationAxis = testing::randomDirection(rng).vector() * testing::uniform(rng, 0.1, 10.0);
        // Every 7th case at exactly 0 or 180 degrees, where axis-angle is most fragile.
        spec.rotationAngleDeg = i % 7 == 0 ? (i % 14 == 0 ? 0.0 : 180.0) : testing::uniform(rng, -360.0, 360.0);
        const auto original = makeShape(spec);
        const ShapeSpec back = describeShape(*original);
        EXPECT_GE(back.rotationAngleDeg, 0.0);
        EXPECT_LE(back.rotationAngleDeg, 180.0);
        EXPECT_EQ(back.center, spec.center);
        EXPECT_LE(matrixDifference(*makeShape(back), *original), kMatrixRelative);
    }
}

TEST(ShapeSpec, EllipsoidFrameIsAProperRotation) {
    for (int i = 0; i < 300; ++i) {
        testing::Rng rng(static_cast<std::uint64_t>(i));
        const Ellipsoid e = testing::randomEllipsoid(rng, Point::Zero(), 1.0);
        const EllipsoidFrame frame = ellipsoidFrame(e);
        EXPECT_NEAR(frame.rotation.determinant(), 1.0, kRecoveredRelative) << "case " << i;
        const Eigen::Matrix3d m =
            frame.rotation * frame.semiAxes.cwiseAbs2().cwiseInverse().asDiagonal() * frame.rotation.transpose();
        EXPECT_LE((m - e.matrix()).cwiseAbs().maxCoeff(), kMatrixRelative * e.matrix().cwiseAbs().maxCoeff())
            << "case " << i;
    }
}

TEST(ShapeSpec, AxisAngleInvertsRotationAboutAxis) {
    for (int i = 0; i < 300; ++i) {
        testing::Rng rng(static_cast<std::uint64_t>(i));
        const Direction axis = testing::randomDirection(rng);
        const double degrees = i == 0 ? 1e-7 : (i == 1 ? 180.0 : testing::uniform(rng, 0.0, 180.0));
        const Eigen::Matrix3d r = rotationAboutAxis(axis, degrees * std::numbers::pi / 180.0);
        const AxisAngle turn = axisAngleOf(r);
        const Eigen::Matrix3d back = rotationAboutAxis(Direction(turn.axis), turn.angleDeg * std::numbers::pi / 180.0);
        EXPECT_LE((back - r).cwiseAbs().maxCoeff(), kRecoveredRelative) << "case " << i;
    }
    const AxisAngle identity = axisAngleOf(Eigen::Matrix3d::Identity());
    EXPECT_EQ(identity.angleDeg, 0.0);
    EXPECT_EQ(identity.axis, Eigen::Vector3d(0.0, 0.0, 1.0));
}

TEST(ShapeSpec, BadValuesAreRefusedWithAClearMessage) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    ShapeSpec sphere;
    sphere.radius = 0.0;
    EXPECT_EQ(refusalOf(sphere), "radius must be > 0");
    sphere.radius = -1.0;
    EXPECT_EQ(refusalOf(sphere), "radius must be > 0");
    sphere.radius = inf;
    EXPECT_EQ(refusalOf(sphere), "radius must be finite");
    sphere.radius = 1.0;
    sphere.center.y() = nan;
    EXPECT_EQ(refusalOf(sphere), "center must be finite");

    ShapeSpec ellipsoid;
    ellipsoid.kind = ShapeKind::Ellipsoid;
    ellipsoid.semiAxes = Eigen::Vector3d(1.0, 0.0, 1.0);
    EXPECT_EQ(refusalOf(ellipsoid), "semi-axes must be > 0");
    ellipsoid.semiAxes = Eigen::Vector3d(1.0, 2.0, 3.0);
    ellipsoid.rotationAxis = Eigen::Vector3d::Zero();
    EXPECT_EQ(refusalOf(ellipsoid), "rotation axis must be a finite, non-zero vector");
    ellipsoid.rotationAxis = Eigen::Vector3d::UnitX();
    ellipsoid.rotationAngleDeg = nan;
    EXPECT_EQ(refusalOf(ellipsoid), "rotation angle must be finite");

    ShapeSpec box;
    box.kind = ShapeKind::Box;
    box.boxMax.y() = -1.0;
    EXPECT_EQ(refusalOf(box), "box max must be > min on every axis (y: max -1 <= min -1)");
    box.boxMax.y() = inf;
    EXPECT_EQ(refusalOf(box), "box corners must be finite");
}

TEST(ShapeSpec, OnlyTheFieldsOfItsKindMatter) {
    ShapeSpec box;
    box.kind = ShapeKind::Box;
    box.radius = -1.0;  // not a sphere: ignored
    box.center = Point(1e300, 0.0, 0.0);
    EXPECT_EQ(refusalOf(box), "accepted");
}

}  // namespace
}  // namespace dropscope
