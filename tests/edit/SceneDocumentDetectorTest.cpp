// SceneDocument detector edits: the loader's rules enforced (a refused edit changes nothing), undo and redo,
// merged drags, and the detectors saved through the scene writer and loaded back.
#include "edit/SceneDocument.hpp"
#include "edit/SceneDocumentTestSupport.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace dropscope {
namespace {

using namespace test;

Detector camera(const std::string& name = "sky") {
    Detector farField;
    farField.name = name;
    farField.type = DetectorType::FarField;
    farField.look = Direction(0, 0, -1);
    farField.fovDeg = 120.0;
    farField.pixels = {64, 64};
    return farField;
}

TEST(SceneDocumentDetectors, AddChangeRemoveUndoAndRedo) {
    SceneDocument document(smallScene());
    EXPECT_TRUE(document.detectors().empty());
    document.addDetector(screen());
    EXPECT_EQ(document.undoLabel(), "add detector \"screen\"");
    document.addDetector(camera());
    ASSERT_EQ(document.detectors().size(), 2u);
    Detector moved = screen();
    moved.center = Point(1, 2, 20);
    document.setDetector(0, moved);
    EXPECT_EQ(document.undoLabel(), "edit detector \"screen\"");
    document.removeDetector(1);
    EXPECT_EQ(document.undoLabel(), "delete detector \"sky\"");
    ASSERT_EQ(document.detectors().size(), 1u);
    EXPECT_EQ(document.detectors()[0].center, Point(1, 2, 20));

    document.undo();  // the camera is back
    ASSERT_EQ(document.detectors().size(), 2u);
    EXPECT_EQ(document.detectors()[1].name, "sky");
    document.undo();  // the plane back where it was added
    EXPECT_EQ(document.detectors()[0].center, Point(0, 0, 20));
    document.undo();
    document.undo();
    EXPECT_TRUE(document.detectors().empty());
    EXPECT_FALSE(document.canUndo());
    for (int k = 0; k < 4; ++k) document.redo();
    ASSERT_EQ(document.detectors().size(), 1u);
    EXPECT_EQ(document.detectors()[0].center, Point(1, 2, 20));
}

TEST(SceneDocumentDetectors, ADuplicateNameOrABadValueIsRefusedAndChangesNothing) {
    SceneDocument document(smallScene());
    document.addDetector(screen());
    const Snapshot before(document);
    EXPECT_EQ(refusalOf([&] { document.addDetector(camera("screen")); }), "detector name \"screen\" is already used");
    Detector flat = screen("flat");
    flat.size = {0.0, 1.0};
    EXPECT_EQ(refusalOf([&] { document.addDetector(flat); }), "detector \"flat\": size must be two numbers > 0");
    Detector wide = camera();
    wide.projection = FarFieldProjection::Perspective;
    wide.fovDeg = 180.0;
    // (checkDetector writes the limit as "180.000000": the prefix is what this test pins.)
    EXPECT_TRUE(
        refusalOf([&] { document.addDetector(wide); }).starts_with("detector \"sky\": fov_deg must be > 0 and < 180"));
    Detector nowhere = screen();
    nowhere.center.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(refusalOf([&] { document.setDetector(0, nowhere); }), "detector \"screen\": center must be finite");
    Detector badName = screen("two words");
    EXPECT_NE(refusalOf([&] { document.setDetector(0, badName); }).find("letters, digits"), std::string::npos);
    Detector alongNormal = screen();
    alongNormal.up = Eigen::Vector3d(0, 0, 2);
    EXPECT_NE(refusalOf([&] { document.setDetector(0, alongNormal); }), "accepted");
    EXPECT_EQ(refusalOf([&] { document.removeDetector(3); }), "there is no detector 3 (1 detectors)");
    EXPECT_EQ(Snapshot(document), before);
}

TEST(SceneDocumentDetectors, ADraggedDetectorIsOneUndoStep) {
    SceneDocument document(smallScene());
    document.addDetector(screen());
    const std::size_t depth = document.undoDepth();
    Detector plane = screen();
    for (int k = 1; k <= 5; ++k) {
        plane.center = Point(0.5 * k, 0, 20);
        document.setDetector(0, plane, k > 1);
    }
    EXPECT_EQ(document.undoDepth(), depth + 1);
    document.undo();
    EXPECT_EQ(document.detectors()[0].center, Point(0, 0, 20));
    // A merge never folds into another kind of step.
    document.redo();
    document.addShape(sphereAt(Point(-4, 0, 0), 0.5));
    document.setDetector(0, screen(), true);
    EXPECT_EQ(document.undoDepth(), depth + 3);
}

TEST(SceneDocumentDetectors, RoundTripThroughTheSceneFile) {
    SceneDocument document(smallScene());
    Detector plane = screen();
    plane.side = DetectorSide::Front;
    plane.absorbing = true;
    plane.up = Eigen::Vector3d(1, 0, 0);
    document.addDetector(plane);
    document.addDetector(camera());
    Detector absorbed;
    absorbed.name = "absorbed";
    absorbed.type = DetectorType::ShapeAbsorption;
    absorbed.record = 10;
    document.addDetector(absorbed);

    const std::string saved = sceneToJson(document.toScene());
    const SceneDocument again{parseScene(saved, "saved.json")};
    ASSERT_EQ(again.detectors().size(), 3u);
    EXPECT_EQ(sceneToJson(again.toScene()), saved);
    const Detector& reloaded = again.detectors()[0];
    EXPECT_EQ(reloaded.center, Point(0, 0, 20));
    EXPECT_EQ(reloaded.side, DetectorSide::Front);
    EXPECT_TRUE(reloaded.absorbing);
    EXPECT_EQ(reloaded.pixels.nx, 32);
    EXPECT_EQ(again.detectors()[1].type, DetectorType::FarField);
    EXPECT_EQ(again.detectors()[1].fovDeg, 120.0);
    EXPECT_EQ(again.detectors()[2].record, 10u);
}

}  // namespace
}  // namespace dropscope
