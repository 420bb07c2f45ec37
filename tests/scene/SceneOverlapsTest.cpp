// Shapes may touch or nest (anything inside a box, a sphere inside a sphere) but not partly overlap.
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using test::sceneErrorOf;
using test::sceneWithShapes;

std::string shapeError(const std::string& shapes) { return sceneErrorOf(sceneWithShapes(shapes)); }

TEST(SceneOverlaps, PartialOverlapNamesBothShapes) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water", "name": "d1"},
                            {"type": "sphere", "center": [1.5, 0, 0], "radius": 1, "medium": "water", "name": "d2"})"),
              R"(scene.json: shapes[1]: sphere "d2" overlaps shapes[0] (sphere "d1"); shapes may touch or nest )"
              R"((anything in a box, a sphere in a sphere), not partly overlap)");
}

TEST(SceneOverlaps, ReportsUnnamedShapesByType) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "sphere", "center": [9, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "box", "min": [0, 0, 0], "max": [2, 2, 2], "medium": "water"})"),
              "scene.json: shapes[2]: box overlaps shapes[0] (sphere); shapes may touch or nest "
              "(anything in a box, a sphere in a sphere), not partly overlap");
}

TEST(SceneOverlaps, TouchingIsAllowed) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "sphere", "center": [2, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "box", "min": [3, -1, -1], "max": [4, 1, 1], "medium": "water"})"),
              "no error");
}

TEST(SceneOverlaps, NestingInABoxIsAllowedInEitherOrder) {
    EXPECT_EQ(shapeError(R"({"type": "box", "min": [-5, -5, -5], "max": [5, 5, 5], "medium": "water"},
                            {"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "ellipsoid", "center": [3, 0, 0], "semi_axes": [1, 2, 1], "medium": "water"},
                            {"type": "box", "min": [-4, -4, 3], "max": [4, 4, 4], "medium": "water"})"),
              "no error");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "box", "min": [-5, -5, -5], "max": [5, 5, 5], "medium": "water"})"),
              "no error");
}

TEST(SceneOverlaps, SphereInsideSphereIsAllowedEvenTouchingFromInside) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                            {"type": "sphere", "center": [0.5, 0, 0], "radius": 0.5, "medium": "water"})"),
              "no error");
}

TEST(SceneOverlaps, OtherNestingIsAnOverlap) {
    // A box inside a sphere, and a sphere inside an ellipsoid: not among the allowed nestings.
    EXPECT_NE(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 5, "medium": "water"},
                            {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "medium": "water"})"),
              "no error");
    EXPECT_NE(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "semi_axes": [5, 4, 3], "medium": "water"},
                            {"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})"),
              "no error");
}

TEST(SceneOverlaps, NestsInside) {
    const Sphere big(Point::Zero(), 2.0);
    const Sphere small(Point(0.5, 0.0, 0.0), 1.0);
    const Sphere poking(Point(1.5, 0.0, 0.0), 1.0);
    const Box box(Point(-3, -3, -3), Point(3, 3, 3));
    EXPECT_TRUE(nestsInside(small, big));
    EXPECT_FALSE(nestsInside(big, small));
    EXPECT_FALSE(nestsInside(poking, big));
    EXPECT_TRUE(nestsInside(big, box));
    EXPECT_FALSE(nestsInside(box, big));
    EXPECT_FALSE(nestsInside(small, Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(3, 3, 3))));
}

}  // namespace
}  // namespace dropscope
