// A parametric shape in the app: drawn, selected by a click (picking through the octree), moved by typing
// into the shape editor's centre field (its translation r0) as one undo step, and undone. The shape is
// the render tests' test-local GeneralShape (tests/render/TestOctahedron.hpp).
#include "AppHarness.hpp"

#include "render/TestOctahedron.hpp"
#include "scene/ShapeSpec.hpp"
#include "snapshot/Image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

namespace dropscope::gui::testing {
namespace {

// Looking straight down -y from 10 above the origin, +x to the right and -z up the screen, so a point
// (x, 0, z) is at pixel (640 + 640 x / (10 tanX), 400 + 400 z / (10 tanY)).
constexpr const char* kTopDownScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "name": "d1", "center": [-3, 0, -2], "radius": 0.3, "medium": "water"}],
  "view": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}
})";

const double kTanY = std::tan(20.0 * std::numbers::pi / 180.0);
const double kTanX = kTanY * 1280.0 / 800.0;

std::pair<float, float> topDownPixel(const Point& p) {
    return {static_cast<float>(640.0 * (1.0 + p.x() / (10.0 * kTanX))),
            static_cast<float>(400.0 * (1.0 + p.z() / (10.0 * kTanY)))};
}

// A drawn shape differs from the background (20, 23, 28) by far more than this, summed over R, G and B.
constexpr int kBackgroundDifference = 60;

bool differsFromBackground(const snapshot::Image& image, const Point& p) {
    const auto [x, y] = topDownPixel(p);
    const std::uint8_t* pixel = image.pixel(static_cast<int>(x), static_cast<int>(y));
    return std::abs(pixel[0] - 20) + std::abs(pixel[1] - 23) + std::abs(pixel[2] - 28) > kBackgroundDifference;
}

// The translation r0 of the general shape in slot `id`; NaN when there is none.
Point translationOf(AppHarness& harness, ShapeId id) {
    const Shape* shape = harness.state().scene.document().octree().shape(id);
    const GeneralShape* general = shape ? asGeneralShape(*shape) : nullptr;
    return general ? general->transform().translation() : Point::Constant(std::numeric_limits<double>::quiet_NaN());
}

// Types `text` into the first box (x) of the shape editor's centre field and leaves the field.
void typeCenterX(AppHarness& harness, const char* text) {
    harness.frame();  // the editor of a shape selected by the last frame's click is drawn in the next one
    harness.typeInto("centre", text);
}

TEST(GeneralShapeUi, ClickedParametricShapeMovesByItsCenterFieldInOneUndoStep) {
    AppHarness harness(kTopDownScene);
    const Eigen::Matrix3d m = Eigen::Vector3d(1.0, 0.5, 1.5).asDiagonal();
    ShapeSpec spec;
    spec.kind = ShapeKind::Parametric;
    spec.general = std::make_shared<test::TestOctahedron>(0.6, AffineTransform(m, Point::Zero()));
    spec.center = Point(1.0, 0.0, 1.0);
    spec.medium = 1;
    const ShapeId id = harness.state().scene.document().addShape(spec);
    harness.frame();
    EXPECT_TRUE(differsFromBackground(harness.image(), Point(1.0, 0.0, 1.0))) << "the shape is not drawn";

    const auto [x, y] = topDownPixel(Point(1.0, 0.0, 1.0));
    harness.click(x, y);
    ASSERT_EQ(harness.state().scene.selectedShape(), id);
    EXPECT_EQ(harness.state().ui.status.text(), "selected shape 1: parametric octahedron, water");

    typeCenterX(harness, "2.5");
    EXPECT_FALSE(harness.state().ui.status.error()) << harness.state().ui.status.text();
    const Shape* moved = harness.state().scene.document().octree().shape(id);
    ASSERT_TRUE(moved && asGeneralShape(*moved));
    EXPECT_EQ(asGeneralShape(*moved)->transform().translation(), Point(2.5, 0.0, 1.0));
    EXPECT_EQ(asGeneralShape(*moved)->transform().matrix(), m) << "only r0 is edited";
    EXPECT_EQ(asGeneralShape(*moved)->presetName(), "octahedron");
    EXPECT_EQ(moved->mediumId(), 1u);
    harness.frame();
    EXPECT_TRUE(differsFromBackground(harness.image(), Point(2.5, 0.0, 1.0))) << "not drawn at its new place";
    EXPECT_FALSE(differsFromBackground(harness.image(), Point(1.0, 0.0, 1.0))) << "still drawn at its old place";

    // Typing "2.5" edited the field three times: one undo step.
    harness.press('Z', true);
    EXPECT_EQ(translationOf(harness, id), Point(1.0, 0.0, 1.0));
    EXPECT_TRUE(differsFromBackground(harness.image(), Point(1.0, 0.0, 1.0)));
    harness.press('Y', true);
    EXPECT_EQ(translationOf(harness, id), Point(2.5, 0.0, 1.0));
}

// Dragging a selected parametric shape moves it like a droplet: r0 follows the cursor in the plane
// through it.
TEST(GeneralShapeUi, DraggingMovesTheSelectedParametricShape) {
    AppHarness harness(kTopDownScene);
    ShapeSpec spec;
    spec.kind = ShapeKind::Parametric;
    spec.general = std::make_shared<test::TestOctahedron>(0.6);
    spec.center = Point(1.0, 0.0, 1.0);
    spec.medium = 1;
    const ShapeId id = harness.state().scene.document().addShape(spec);
    const auto [x, y] = topDownPixel(Point(1.0, 0.0, 1.0));
    harness.click(x, y);
    ASSERT_EQ(harness.state().scene.selectedShape(), id);
    harness.drag(x, y, x + 64.0f, y);
    // 64 pixels right is 64/640 of 10 tanX; float mouse coordinates round a little.
    constexpr double kMouseRounding = 1e-6;
    EXPECT_NEAR(translationOf(harness, id).x(), 1.0 + 0.1 * 10.0 * kTanX, kMouseRounding);
    EXPECT_NEAR(translationOf(harness, id).z(), 1.0, kMouseRounding);
    harness.press('Z', true);
    EXPECT_EQ(translationOf(harness, id), Point(1.0, 0.0, 1.0));
}

// A torus from a scene file, lying flat under the top-down camera: a click on its tube selects it, a
// click in its hole selects nothing (the pick goes through the octree to the exact, non-convex shape).
TEST(GeneralShapeUi, AClickInATorusHoleSelectsNothingAndOnItsTubeSelectsIt) {
    constexpr const char* torusScene = R"({
      "dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "glass": {"n": 1.5}},
      "shapes": [{"type": "parametric", "preset": "torus", "major_radius": 1, "minor_radius": 0.3,
                  "transform": {"rotation": {"axis": [1, 0, 0], "angle_deg": 90}}, "medium": "glass"}],
      "view": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}
    })";
    AppHarness harness(torusScene);
    const auto [holeX, holeY] = topDownPixel(Point(0.0, 0.0, 0.0));
    const auto [tubeX, tubeY] = topDownPixel(Point(1.0, 0.0, 0.0));
    EXPECT_FALSE(differsFromBackground(harness.image(), Point(0.0, 0.0, 0.0)));
    EXPECT_TRUE(differsFromBackground(harness.image(), Point(1.0, 0.0, 0.0)));
    harness.click(holeX, holeY);
    EXPECT_EQ(harness.state().scene.selectedShape(), RayHit::kNone);
    harness.click(tubeX, tubeY);
    EXPECT_EQ(harness.state().scene.selectedShape(), 0u);
    EXPECT_EQ(harness.state().ui.status.text(), "selected shape 0: parametric torus, glass");
    harness.frame();
    EXPECT_EQ(harness.itemRects().count("centre"), 1u) << "the editor shows the centre field";
}

}  // namespace
}  // namespace dropscope::gui::testing
