#include "render/Camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope::render {
namespace {

// Camera state is double precision: a few roundings of unit-sized values.
constexpr double kCameraRounding = 1e-12;

TEST(Camera, OrbitKeepsTheDistanceToTheTargetAndTurnsAboutUp) {
    Camera camera;
    camera.eye = {3, 1, 4};
    camera.target = {1, 1, 1};
    const double distance = glm::length(camera.eye - camera.target);
    camera.orbit(0.5 * std::acos(-1.0), 0.0);  // a quarter turn about +y
    EXPECT_NEAR(glm::length(camera.eye - camera.target), distance, kCameraRounding);
    EXPECT_NEAR(camera.eye.y, 1.0, kCameraRounding);  // no height change without pitch
    // (2, 0, 3) from the target turned a quarter about +y is (3, 0, -2).
    EXPECT_NEAR(camera.eye.x - 1.0, 3.0, kCameraRounding);
    EXPECT_NEAR(camera.eye.z - 1.0, -2.0, kCameraRounding);
    camera.orbit(0.0, 0.3);
    EXPECT_NEAR(glm::length(camera.eye - camera.target), distance, kCameraRounding);
    EXPECT_GT(std::abs(camera.eye.y - 1.0), 0.1);
}

TEST(Camera, OrbitStopsShortOfThePole) {
    Camera camera;
    camera.eye = {0, 0, 5};
    camera.target = {0, 0, 0};
    for (int i = 0; i < 100; ++i) camera.orbit(0.0, 0.1);
    const glm::dvec3 direction = glm::normalize(camera.eye - camera.target);
    EXPECT_LT(std::abs(glm::dot(direction, glm::normalize(camera.up))), 0.995 + kCameraRounding);
}

TEST(Camera, PanMovesEyeAndTargetTogetherZoomScalesTheDistance) {
    Camera camera;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    camera.fovDeg = 90.0;  // the visible height at the target is 2 * 10 * tan(45) = 20
    camera.pan(0.25, -0.5);
    EXPECT_NEAR(camera.target.x, 5.0, kCameraRounding);
    EXPECT_NEAR(camera.target.y, -10.0, kCameraRounding);
    EXPECT_NEAR(glm::length(camera.eye - camera.target), 10.0, kCameraRounding);
    camera.zoom(0.5);
    EXPECT_NEAR(glm::length(camera.eye - camera.target), 5.0, kCameraRounding);
}

TEST(Camera, FitToPutsEveryCornerOfTheBoundsInTheImage) {
    const Eigen::AlignedBox3d bounds(Point(-3, 10, 2), Point(5, 11, 9));
    for (double aspect : {0.5, 1.0, 2.0}) {
        Camera camera;
        camera.fitTo(bounds, aspect);
        const int height = 400;
        const int width = static_cast<int>(height * aspect);
        EXPECT_NEAR(glm::length(camera.target - glm::dvec3(1, 10.5, 5.5)), 0.0, kCameraRounding);
        double largest = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            const Point p = bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
            const glm::dvec3 pixel = camera.project({p.x(), p.y(), p.z()}, width, height);
            EXPECT_GE(pixel.x, 0.0);
            EXPECT_LE(pixel.x, width);
            EXPECT_GE(pixel.y, 0.0);
            EXPECT_LE(pixel.y, height);
            EXPECT_GT(pixel.z, 0.0);  // between the near and far planes
            EXPECT_LT(pixel.z, 1.0);
            largest = std::max({largest, std::abs(pixel.x - width / 2.0) / (width / 2.0),
                                std::abs(pixel.y - height / 2.0) / (height / 2.0)});
        }
        EXPECT_GT(largest, 0.5);  // fitted, not lost in the middle
    }
}

TEST(Camera, ASceneViewRoundTrips) {
    const SceneView view{Point(1, 2, 3), Point(4, 5, 6), Direction(0, 0, 1), 33.0};
    const SceneView back = Camera::fromView(view).toView();
    EXPECT_EQ(back.eye, view.eye);
    EXPECT_EQ(back.target, view.target);
    EXPECT_EQ(back.up.vector(), view.up.vector());
    EXPECT_EQ(back.fovDeg, view.fovDeg);
}

}  // namespace
}  // namespace dropscope::render
