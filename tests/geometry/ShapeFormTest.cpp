// Shape::sameFormAs (an edit that only moves a shape) and Shape::mayMeetBox (the overlap tests'
// cell test), for every shape type, against what they must say.
#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using testing::Rng;

TEST(ShapeForm, AMovedShapeHasTheSameFormAndAResizedOrOtherOneNot) {
    const Eigen::Matrix3d rotation = rotationAboutAxis(Direction(1, 2, 3), 0.7);
    const Eigen::Vector3d semiAxes(1.0, 0.5, 0.25);
    EXPECT_TRUE(Sphere(Point(1, 2, 3), 0.5).sameFormAs(Sphere(Point(-7, 0, 1e3), 0.5)));
    EXPECT_FALSE(Sphere(Point(1, 2, 3), 0.5).sameFormAs(Sphere(Point(1, 2, 3), 0.5000001)));
    EXPECT_TRUE(Ellipsoid::fromSemiAxes(Point::Zero(), semiAxes, rotation)
                    .sameFormAs(Ellipsoid::fromSemiAxes(Point(4, 5, 6), semiAxes, rotation)));
    EXPECT_FALSE(Ellipsoid::fromSemiAxes(Point::Zero(), semiAxes, rotation)
                     .sameFormAs(Ellipsoid::fromSemiAxes(Point::Zero(), semiAxes)));
    // A box moved by a translation that does not keep its edges' bits is still the same box.
    const Box box(Point(0.1, 0.2, 0.3), Point(0.4, 0.7, 1.3));
    const Eigen::Vector3d shift(1e3 / 3.0, -1e-3 / 7.0, 0.3);
    const Box moved(box.lower() + shift, box.upper() + shift);
    ASSERT_NE(moved.edgeLengths(), box.edgeLengths()) << "the shift is meant to round the edges";
    EXPECT_TRUE(box.sameFormAs(moved));
    EXPECT_FALSE(box.sameFormAs(Box(box.lower(), box.upper() + Eigen::Vector3d(1e-6, 0, 0))));
    // Never across types, even where the bodies coincide.
    EXPECT_FALSE(Sphere(Point::Zero(), 1.0).sameFormAs(Ellipsoid::fromSemiAxes(Point::Zero(), {1.0, 1.0, 1.0})));
    EXPECT_FALSE(Ellipsoid::fromSemiAxes(Point::Zero(), {1.0, 1.0, 1.0}).sameFormAs(Sphere(Point::Zero(), 1.0)));
    EXPECT_FALSE(Box(Point::Zero(), Point::Ones()).sameFormAs(Sphere(Point::Zero(), 1.0)));
}

// Some point of an n^3 grid over the box is inside or on the shape.
bool gridPointInside(const Shape& shape, const Eigen::AlignedBox3d& box, int n) {
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
            for (int c = 0; c < n; ++c) {
                const Eigen::Vector3d at = Eigen::Vector3d(a, b, c) / (n - 1.0);
                if (shape.locatePoint(box.min() + (box.max() - box.min()).cwiseProduct(at)) != PointLocation::Outside) {
                    return true;
                }
            }
    return false;
}

TEST(ShapeForm, MayMeetBoxIsExactForTheAnalyticShapes) {
    // Against brute force: a box with a grid point in the body must be met (the overlap tests rely on
    // that), and a box that is met must have body points within kReach of it (a sliver of overlap is
    // found once the box is grown by more than the grid's spacing).
    constexpr double kReach = 0.03;
    int met = 0, apart = 0;
    for (int i = 0; i < 600; ++i) {
        SCOPED_TRACE(::testing::Message() << "case " << i);
        Rng rng(static_cast<unsigned>(i));
        const auto shape = testing::randomShape(rng, i, Point::Zero(), 1.0);
        // Boxes about as often apart from the body as meeting it: around its bounds' surface.
        const Point corner =
            testing::randomPoint(rng, 0.3 * testing::boundsDiagonal(*shape), testing::boundsCenter(*shape));
        const Eigen::AlignedBox3d box(corner, corner + Eigen::Vector3d::Constant(testing::uniform(rng, 0.05, 0.3)));
        const bool mayMeet = shape->mayMeetBox(box);
        if (gridPointInside(*shape, box, 9)) {
            EXPECT_TRUE(mayMeet) << *shape;
        }
        if (mayMeet) {
            const Eigen::Vector3d grow = Eigen::Vector3d::Constant(kReach);
            EXPECT_TRUE(gridPointInside(*shape, Eigen::AlignedBox3d(box.min() - grow, box.max() + grow), 17)) << *shape;
        }
        (mayMeet ? met : apart) += 1;
    }
    EXPECT_GT(met, 100);
    EXPECT_GT(apart, 100);
}

}  // namespace
}  // namespace dropscope
