// The Detectors panel and the detector handles, driven as a user does: select in the list, drag the handles
// in the view, G and A, fields typed in (refusals in the status line), add and remove, undo.
#include "AppHarness.hpp"

#include "gui/DetectorDefaults.hpp"
#include "gui/DetectorHandles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope::gui::testing {
namespace {

constexpr double kMouseRounding = 1e-6;

// Looking straight down -y from 10 above the origin, +x to the right and -z up the screen (AppUiTest's
// top-down view), with a plane detector below the droplet facing -z and a far-field camera.
constexpr const char* kDetectorScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "name": "d1", "center": [2, 0, 2], "radius": 0.5, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]}],
  "detectors": [
    {"type": "plane", "name": "screen", "center": [0, 0, 3], "normal": [0, 0, -1], "up": [0, 1, 0],
     "size": [4, 2], "pixels": [8, 4]},
    {"type": "far_field", "name": "sky", "look": [0, 0, 1], "up": [0, 1, 0], "fov_deg": 90, "pixels": [16, 16]}],
  "view": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}
})";

const double kTanY = std::tan(20.0 * std::numbers::pi / 180.0);
const double kTanX = kTanY * 1280.0 / 800.0;
// A pixel of the top-down view on the plane y = 0: the point under the cursor is within one of the one aimed at.
const double kPixel = 2.0 * 10.0 * kTanX / 1280.0;

std::pair<float, float> topDownPixel(const Point& p) {
    return {static_cast<float>(640.0 * (1.0 + p.x() / (10.0 * kTanX))),
            static_cast<float>(400.0 * (1.0 + p.z() / (10.0 * kTanY)))};
}

const Detector& detectorAt(AppHarness& harness, std::size_t index) {
    return harness.state().scene.document().detectors().at(index);
}

TEST(DetectorUi, TheLayerAndPanelAreOnForASceneWithDetectorsAndTheGlyphsAreDrawn) {
    AppHarness harness(kDetectorScene);
    EXPECT_TRUE(harness.state().view.layers.detectors);
    ASSERT_TRUE(harness.item("detector screen"));
    bool cyan = false;
    for (const render::LineVertex& vertex : harness.app().viewport().layers().lines.vertices()) {
        cyan = cyan || vertex.colour == render::kDetectorColour;
    }
    EXPECT_TRUE(cyan) << "the detector glyphs are among the view's lines";
}

TEST(DetectorUi, DraggingAPlanesHandlesMovesAndAimsItEachDragOneUndoStep) {
    AppHarness harness(kDetectorScene);
    ASSERT_TRUE(harness.clickItem("detector screen"));
    ASSERT_EQ(harness.state().scene.selectedDetector(), std::optional<std::size_t>(0));
    harness.frames(2);
    const double arrow = render::planeArrowLength(
        detectorAt(harness, 0), render::kSourceGlyph * harness.app().viewport().sceneBounds().diagonal().norm());

    const auto [mx, my] = topDownPixel(Point(0, 0, 3));
    harness.drag(mx, my, mx + 64.0f, my);  // 64 pixels right: 0.1 of 10 tanX along +x
    const Point moved(0.1 * 10.0 * kTanX, 0.0, 3.0);
    EXPECT_NEAR((detectorAt(harness, 0).center - moved).norm(), 0.0, kMouseRounding);
    EXPECT_EQ(harness.state().scene.selectedShape(), RayHit::kNone);

    const auto [ax, ay] = topDownPixel(moved - arrow * Eigen::Vector3d::UnitZ());  // the arrow's tip, along the normal
    harness.drag(ax, ay, ax + 80.0f, ay);  // the tip 80 pixels right: +x by 0.125 of 10 tanX
    const Eigen::Vector3d aimed = Eigen::Vector3d(0.125 * 10.0 * kTanX, 0.0, -arrow).normalized();
    const Detector& plane = detectorAt(harness, 0);
    EXPECT_NEAR((plane.normal.vector() - aimed).norm(), 0.0, kMouseRounding);
    EXPECT_NEAR(plane.up.dot(plane.normal.vector()), 0.0, 1e-12) << "up turned with the normal";

    harness.press('Z', true);
    EXPECT_EQ(detectorAt(harness, 0).normal.vector(), Eigen::Vector3d(0, 0, -1));
    harness.press('Z', true);
    EXPECT_EQ(detectorAt(harness, 0).center, Point(0, 0, 3));
    EXPECT_EQ(firstSource(harness).origin, Point(0, 0, -5)) << "the source was not touched";
}

TEST(DetectorUi, GMovesTheSelectedDetectorAndAAimsAFarFieldCameraFromThePointUnderTheCursor) {
    AppHarness harness(kDetectorScene);
    harness.state().scene.selectDetector(0);
    const auto [gx, gy] = topDownPixel(Point(-1, 0, 1));
    harness.moveMouse(gx, gy);
    harness.press('G');
    EXPECT_LT((detectorAt(harness, 0).center - Point(-1, 0, 1)).norm(), kPixel);
    EXPECT_EQ(firstSource(harness).origin, Point(0, 0, -5)) << "G went to the detector, not the source";

    harness.state().scene.selectDetector(1);
    const Point centre = harness.app().viewport().sceneBounds().center();
    const auto [px, py] = topDownPixel(Point(centre.x() - 3.0, 0, centre.z()));
    harness.moveMouse(px, py);
    harness.press('A');
    EXPECT_LT((detectorAt(harness, 1).look.vector() - Eigen::Vector3d::UnitX()).norm(), kPixel / 3.0)
        << "looking from -x at the scene";
    harness.press('G');
    EXPECT_TRUE(harness.state().ui.status.error()) << "a far-field camera has no place to move";
}

TEST(DetectorUi, FieldsAreCheckedByTheDocumentAndARefusalIsShownInTheStatusLine) {
    AppHarness harness(kDetectorScene);
    ASSERT_TRUE(harness.clickItem("detector screen"));
    harness.frames(2);
    ASSERT_TRUE(harness.typeInto("name", "sky"));
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_EQ(harness.state().ui.status.text(), "detector not changed: detector name \"sky\" is already used");
    EXPECT_EQ(detectorAt(harness, 0).name, "screen");
    ASSERT_TRUE(harness.typeInto("size", "0"));
    EXPECT_EQ(harness.state().ui.status.text(),
              "detector not changed: detector \"screen\": size must be two numbers > 0");
    ASSERT_TRUE(harness.typeInto("size", "6"));
    EXPECT_EQ(detectorAt(harness, 0).size[0], 6.0);
    EXPECT_EQ(harness.state().scene.document().undoLabel(), "edit detector \"screen\"");
}

TEST(DetectorUi, AddPlacesDefaultsFromTheSceneAndRemoveUndoes) {
    AppHarness harness(kDetectorScene);
    ASSERT_TRUE(harness.clickItem("Add plane"));
    ASSERT_EQ(harness.state().scene.document().detectors().size(), 3u);
    const Detector& plane = detectorAt(harness, 2);
    EXPECT_EQ(plane.name, "screen-2");
    EXPECT_EQ(plane.normal.vector(), Eigen::Vector3d(0, 0, -1)) << "facing the source";
    EXPECT_GT(plane.center.z(), 2.5) << "behind the droplet";
    EXPECT_EQ(harness.state().scene.selectedDetector(), std::optional<std::size_t>(2));
    harness.frames(2);
    ASSERT_TRUE(harness.clickItem("Add far-field"));
    EXPECT_EQ(detectorAt(harness, 3).name, "sky-2");
    EXPECT_EQ(detectorAt(harness, 3).look.vector(), Eigen::Vector3d(0, 0, 1)) << "along the source's direction";
    harness.frames(2);
    ASSERT_TRUE(harness.clickItem("Remove detector"));
    EXPECT_EQ(harness.state().scene.document().detectors().size(), 3u);
    harness.press('Z', true);
    EXPECT_EQ(harness.state().scene.document().detectors().size(), 4u);
}

TEST(DetectorDefaults, AShapeAbsorptionDetectorNeedsOnlyAName) {
    SceneDocument document(parseScene(kDetectorScene, "test.json"));
    const Detector absorbed = defaultDetector(document, DetectorType::ShapeAbsorption);
    EXPECT_EQ(absorbed.name, "absorbed");
    EXPECT_NO_THROW(checkDetector(absorbed));
    EXPECT_EQ(unusedDetectorName(document, "sky"), "sky-2");
}

}  // namespace
}  // namespace dropscope::gui::testing
