// Parametric and implicit shapes in the editable document: described, moved by their translation, undone.
#include "edit/SceneDocument.hpp"
#include "edit/SceneDocumentTestSupport.hpp"
#include "scene/ShapeSpec.hpp"

#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/parametric/ParametricShape.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using namespace test;

// A torus lying in a plane tilted about x, and a blob, beside the small scene's droplets.
Scene sceneWithGeneralShapes() {
    return parseScene(R"({"dropscope": 1, "ambient": "air",
        "media": {"air": {"n": 1.0}, "water": {"n": 1.333}},
        "shapes": [
          {"type": "sphere", "name": "d1", "center": [0, 0, 0], "radius": 1, "medium": "water"},
          {"type": "parametric", "preset": "torus", "name": "ring", "major_radius": 1, "minor_radius": 0.25,
           "transform": {"rotation": {"axis": [1, 0, 0], "angle_deg": 90}, "translation": [4, 0, 0]}, "medium": "water"},
          {"type": "implicit", "preset": "blob", "name": "pair", "centers": [[0, 0, 0], [0.8, 0, 0]],
           "radii": [0.5, 0.5], "blend": 0.1, "transform": {"translation": [-4, 0, 0]}, "medium": "water"}]})",
                      "general.json");
}

TEST(GeneralShapeEdit, DescribeAndMakeGiveTheSameShapeSharingItsBase) {
    const Scene scene = sceneWithGeneralShapes();
    const auto& ring = static_cast<const ParametricShape&>(*scene.shapes[1]);
    const ShapeSpec spec = describeShape(ring);
    EXPECT_EQ(spec.kind, ShapeKind::Parametric);
    EXPECT_EQ(spec.center, Point(4, 0, 0));
    const std::unique_ptr<Shape> made = makeShape(withCenter(spec, Point(6, 1, 0)));
    const auto& moved = static_cast<const ParametricShape&>(*made);
    EXPECT_EQ(moved.base(), ring.base());
    EXPECT_EQ(moved.transform().matrix(), ring.transform().matrix());
    EXPECT_EQ(moved.transform().translation(), Eigen::Vector3d(6, 1, 0));
    EXPECT_EQ(moved.mediumId(), ring.mediumId());
    EXPECT_NEAR(moved.xMax() - ring.xMax(), 2.0, 1e-12);
    EXPECT_EQ(moved.volume(), ring.volume());
}

TEST(GeneralShapeEdit, MovingIsOneUndoStepAndTheOctreeFollows) {
    SceneDocument document(sceneWithGeneralShapes());
    // The ring stands in the xz plane around (4, 0, 0): a ray down the z axis at x = 5 meets its tube.
    EXPECT_EQ(hitFrom(document, Point(5, 0, -5), Eigen::Vector3d::UnitZ()), 1u);
    document.modifyShape(1, withCenter(describeShape(*document.shape(1)), Point(4, 5, 0)));
    EXPECT_EQ(hitFrom(document, Point(5, 0, -5), Eigen::Vector3d::UnitZ()), RayHit::kNone);
    EXPECT_EQ(hitFrom(document, Point(5, 5, -5), Eigen::Vector3d::UnitZ()), 1u);
    EXPECT_EQ(document.undoLabel().find("move"), 0u) << document.undoLabel();
    document.undo();
    EXPECT_EQ(hitFrom(document, Point(5, 0, -5), Eigen::Vector3d::UnitZ()), 1u);
    // The blob's neck, between its two droplets, is hit from above.
    EXPECT_EQ(hitFrom(document, Point(-3.6, 0, 5), -Eigen::Vector3d::UnitZ()), 2u);
}

TEST(GeneralShapeEdit, AMoveIntoAnotherShapeIsRefused) {
    SceneDocument document(sceneWithGeneralShapes());
    const Snapshot before(document);
    const std::string refusal =
        refusalOf([&] { document.modifyShape(2, withCenter(describeShape(*document.shape(2)), Point(-0.8, 0, 0))); });
    EXPECT_NE(refusal.find("implicit blob"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("overlap"), std::string::npos) << refusal;
    EXPECT_TRUE(Snapshot(document) == before);
}

}  // namespace
}  // namespace dropscope
