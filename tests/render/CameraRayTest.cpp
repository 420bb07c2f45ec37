#include "render/Camera.hpp"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace dropscope::render {
namespace {

// A few double roundings of unit-sized values; in pixels, those times the image size (~1e3).
constexpr double kUnitRounding = 1e-14;
constexpr double kPixelRounding = 1e-9;

// Picking inverts projection: a point along rayThrough(x, y) projects back onto (x, y).
TEST(CameraRay, ProjectsBackOntoThePixelItWasCastThrough) {
    Camera camera;
    camera.eye = {4.0, -1.5, 7.0};
    camera.target = {0.5, 0.2, -0.3};
    camera.fovDeg = 35.0;
    const int width = 640;
    const int height = 400;
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {320.0, 200.0}, {12.5, 377.25}, {639.0, 1.0}, {100.0, 300.0}}) {
        const glm::dvec3 direction = camera.rayThrough(x, y, width, height);
        EXPECT_NEAR(glm::length(direction), 1.0, kUnitRounding);
        const glm::dvec3 pixel = camera.project(camera.eye + 5.0 * direction, width, height);
        EXPECT_NEAR(pixel.x, x, kPixelRounding) << x << ", " << y;
        EXPECT_NEAR(pixel.y, y, kPixelRounding) << x << ", " << y;
    }
}

TEST(CameraRay, TheImageCenterLooksAtTheTarget) {
    Camera camera;
    camera.eye = {0.0, 10.0, 0.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.up = {0.0, 0.0, -1.0};
    const glm::dvec3 direction = camera.rayThrough(400.0, 300.0, 800, 600);
    EXPECT_NEAR(direction.x, 0.0, kUnitRounding);
    EXPECT_NEAR(direction.y, -1.0, kUnitRounding);
    EXPECT_NEAR(direction.z, 0.0, kUnitRounding);
}

}  // namespace
}  // namespace dropscope::render
