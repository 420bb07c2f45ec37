// Scene key "view": {"eye", "target", "up" (optional), "fov_deg" (optional, 0 < f < 180)}, the renderer's
// starting camera (docs/scene-format.md).
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace dropscope {
namespace {

using test::sceneErrorOf;

std::string withView(const std::string& view) { return R"({"dropscope": 1, "view": )" + view + "}"; }

TEST(SceneView, IsReadWithDefaults) {
    EXPECT_FALSE(parseScene(R"({"dropscope": 1})", "scene.json").view.has_value());

    const Scene scene = parseScene(withView(R"({"eye": [1, 2, 3], "target": [0, 0, -1]})"), "scene.json");
    ASSERT_TRUE(scene.view.has_value());
    EXPECT_EQ(scene.view->eye, Point(1, 2, 3));
    EXPECT_EQ(scene.view->target, Point(0, 0, -1));
    EXPECT_EQ(scene.view->up.vector(), Eigen::Vector3d::UnitY());
    EXPECT_EQ(scene.view->fovDeg, SceneView{}.fovDeg);
}

TEST(SceneView, UpIsNormalisedAndFovKept) {
    const Scene scene = parseScene(
        withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0.5, 0.5], "fov_deg": 179.5})"), "scene.json");
    ASSERT_TRUE(scene.view.has_value());
    EXPECT_NEAR(scene.view->up.y(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(scene.view->up.z(), std::sqrt(0.5), 1e-15);
    EXPECT_EQ(scene.view->fovDeg, 179.5);
}

TEST(SceneView, EyeAndTargetMustDiffer) {
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [1, 2, 3], "target": [1, 2, 3]})")),
              "scene.json: view.target: must differ from eye");
}

TEST(SceneView, UpMustNotBeParallelToTheViewDirection) {
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, 2]})")),
              "scene.json: view.up: must not be parallel to target - eye");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, -1]})")),
              "scene.json: view.up: must not be parallel to target - eye");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, 0]})")),
              "scene.json: view.up: must be a non-zero vector");
}

TEST(SceneView, FovMustBeBetween0And180) {
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "fov_deg": 0})")),
              "scene.json: view.fov_deg: must be > 0");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "fov_deg": -10})")),
              "scene.json: view.fov_deg: must be > 0");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "fov_deg": 180})")),
              "scene.json: view.fov_deg: must be < 180, got 180");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "fov_deg": 212.5})")),
              "scene.json: view.fov_deg: must be < 180, got 212.5");
}

TEST(SceneView, MissingMalformedOrUnknownKeysAreErrors) {
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "fov_dg": 30})")),
              R"(scene.json: view: unknown key "fov_dg" (did you mean "fov_deg"?))");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "zoom": 2})")),
              R"(scene.json: view: unknown key "zoom" (valid keys: eye, target, up, fov_deg))");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0, 5]})")), R"(scene.json: view: missing required key "target")");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, 0], "target": [0, 0, 0]})")),
              "scene.json: view.eye: expected an array of 3 numbers, got 2 elements");
    EXPECT_EQ(sceneErrorOf(withView(R"({"eye": [0, "1", 5], "target": [0, 0, 0]})")),
              "scene.json: view.eye[1]: expected a number, got string");
    EXPECT_EQ(sceneErrorOf(withView("[1, 2]")), "scene.json: view: expected an object, got array");
}

}  // namespace
}  // namespace dropscope
