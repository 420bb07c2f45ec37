// SceneDocument shape edits: they keep the octree exact and the scene valid, a refusal changes
// nothing, ids never change.
#include "edit/SceneDocument.hpp"
#include "edit/SceneDocumentTestSupport.hpp"

#include "geometry/Box.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneOverlaps.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using namespace test;

TEST(SceneDocument, KeepsTheLoadedIdsNamesAndSettings) {
    const SceneDocument document(smallScene());
    EXPECT_EQ(document.shapeCount(), 3u);
    EXPECT_EQ(document.nameOf(1), "d2");
    EXPECT_EQ(document.findShape("cell"), 2u);
    EXPECT_EQ(document.shape(2)->kind(), ShapeKind::Box);
    EXPECT_EQ(document.media().size(), 3u);
    EXPECT_EQ(document.ambient(), 0u);
    EXPECT_EQ(document.sources().size(), 1u);
    EXPECT_EQ(document.origin(), "small.json");
    EXPECT_EQ(hitFrom(document, Point(3, 0, -5), Eigen::Vector3d::UnitZ()), 1u);
    EXPECT_FALSE(document.canUndo());
    EXPECT_FALSE(document.canRedo());
}

TEST(SceneDocument, AddedShapeIsFoundByFirstHit) {
    SceneDocument document(smallScene());
    const std::uint64_t before = document.revision();
    const ShapeId id = document.addShape(sphereAt(Point(-4, 0, 0), 0.5), "d3");
    EXPECT_EQ(id, 3u);
    EXPECT_GT(document.revision(), before);
    EXPECT_EQ(document.shapeCount(), 4u);
    EXPECT_EQ(document.nameOf(id), "d3");
    const RayHit hit = document.octree().firstHit(Point(-4, 0, -5), Direction(0, 0, 1));
    EXPECT_EQ(hit.shape, id);
    EXPECT_DOUBLE_EQ(hit.distance, 4.5);
    EXPECT_EQ(document.undoLabel(), "add sphere \"d3\"");
}

TEST(SceneDocument, OverlappingAddIsRefusedNamingTheOtherShapeAndChangesNothing) {
    SceneDocument document(smallScene());
    document.addShape(sphereAt(Point(-4, 0, 0), 0.5));
    document.undo();  // something to redo, which a refusal must keep
    const Snapshot before(document);
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(1.5, 0, 0), 1.0)); }),
              "sphere would overlap shape 0 (sphere \"d1\")");
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(-4, 0, 0), 0.5), "d1"); }),
              "name \"d1\" is already used by shape 0");
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(-4, 0, 0), 0.0)); }), "radius must be > 0");
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(-4, 0, 0), 0.5, 9)); }),
              "medium 9 is not defined (3 media)");
    EXPECT_EQ(Snapshot(document), before);
    EXPECT_TRUE(document.canRedo());
}

TEST(SceneDocument, TouchingAndNestingAreAcceptedOtherOverlapsAreNot) {
    SceneDocument document(smallScene());
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0, 2, 0), 1.0)));    // touches d1
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0, 0, 7), 1.0)));    // in the cell
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0.2, 0, 0), 0.5)));  // in d1
    ShapeSpec box;
    box.kind = ShapeKind::Box;
    box.boxMin = Point(-0.3, -0.3, -0.3);
    box.boxMax = Point(0.3, 0.3, 0.3);
    EXPECT_EQ(document.checkPlacement(box), "box would overlap shape 0 (sphere \"d1\")");  // a box in a sphere
    ShapeSpec around;  // a box around d2: d2 nests in it
    around.kind = ShapeKind::Box;
    around.boxMin = Point(1.9, -1.1, -1.1);
    around.boxMax = Point(4.1, 1.1, 1.1);
    EXPECT_EQ(document.checkPlacement(around), std::nullopt);
    EXPECT_EQ(document.shapeCount(), 6u);
}

TEST(SceneDocument, ModifyMovesTheShape) {
    SceneDocument document(smallScene());
    document.modifyShape(1, sphereAt(Point(3, 3, 0), 1.0));
    EXPECT_EQ(hitFrom(document, Point(3, 3, -5), Eigen::Vector3d::UnitZ()), 1u);
    EXPECT_EQ(hitFrom(document, Point(3, 0, -5), Eigen::Vector3d::UnitZ()), 2u);  // through to the cell
    EXPECT_EQ(document.nameOf(1), "d2");
    EXPECT_EQ(document.undoLabel(), "move sphere \"d2\"");
    // The shape itself is not in the way of its own move; others are.
    EXPECT_NO_THROW(document.modifyShape(1, sphereAt(Point(3, 3.5, 0), 1.0)));
    EXPECT_EQ(refusalOf([&] { document.modifyShape(1, sphereAt(Point(1, 0, 0), 1.0)); }),
              "sphere would overlap shape 0 (sphere \"d1\")");
    EXPECT_EQ(document.checkPlacement(sphereAt(Point(3, 3.2, 0), 1.0), ShapeId{1}), std::nullopt);
    EXPECT_NE(document.checkPlacement(sphereAt(Point(3, 3.2, 0), 1.0)), std::nullopt);
    document.modifyShape(1, sphereAt(Point(3, 3.5, 0), 1.2));
    EXPECT_EQ(document.undoLabel(), "edit sphere \"d2\"");
    EXPECT_EQ(refusalOf([&] { document.modifyShape(7, sphereAt(Point(30, 0, 0), 1.0)); }), "there is no shape 7");
}

TEST(SceneDocument, RemoveThenUndoRestoresTheSameIdAndGeometry) {
    SceneDocument document(smallScene());
    const Sphere original = static_cast<const Sphere&>(*document.shape(0));
    document.removeShape(0);
    EXPECT_EQ(document.shape(0), nullptr);
    EXPECT_EQ(document.shapeCount(), 2u);
    EXPECT_EQ(document.slotCount(), 3u);
    EXPECT_EQ(document.findShape("d1"), std::nullopt);
    EXPECT_EQ(hitFrom(document, Point(0, 0, -5), Eigen::Vector3d::UnitZ()), 2u);  // through to the cell
    EXPECT_EQ(document.undoLabel(), "delete sphere \"d1\"");
    EXPECT_EQ(refusalOf([&] { document.removeShape(0); }), "there is no shape 0");
    document.undo();
    ASSERT_NE(document.shape(0), nullptr);
    const auto& restored = static_cast<const Sphere&>(*document.shape(0));
    EXPECT_EQ(restored.center(), original.center());
    EXPECT_EQ(restored.radius(), original.radius());
    EXPECT_EQ(restored.mediumId(), original.mediumId());
    EXPECT_EQ(document.nameOf(0), "d1");
    EXPECT_EQ(document.findShape("d1"), 0u);
    EXPECT_EQ(hitFrom(document, Point(0, 0, -5), Eigen::Vector3d::UnitZ()), 0u);
}

TEST(SceneDocument, GeneratedCloudOverlapsNothingAndUndoesInOneStep) {
    SceneDocument document(smallScene());
    DropletCloudSpec spec;
    spec.region = Eigen::AlignedBox3d(Point(-4, -4, -4), Point(4, 4, 8));  // around d1, d2, into the cell
    spec.count = 400;
    spec.radius = RadiusDistribution::lognormal(0.15, 0.3, 0.0, 0.4);
    spec.seed = 3;
    const Snapshot before(document);
    const std::vector<ShapeId> ids = document.generateCloud(spec, 1);
    ASSERT_EQ(ids.size(), 400u);
    EXPECT_EQ(document.shapeCount(), 403u);
    EXPECT_EQ(document.undoLabel(), "generate 400 droplets");
    EXPECT_EQ(document.undoDepth(), 1u);
    // Brute force: the whole scene obeys the overlap rule.
    const Scene scene = document.toScene();
    EXPECT_NO_THROW(checkShapesDisjoint(scene));
    for (std::size_t a = 0; a < scene.shapes.size(); ++a) {
        for (std::size_t b = 0; b < a; ++b) {
            const Shape& x = *scene.shapes[a];
            const Shape& y = *scene.shapes[b];
            EXPECT_TRUE(!x.overlaps(y) || nestsInside(x, y) || nestsInside(y, x)) << a << " " << b;
        }
    }
    for (const ShapeId id : ids) {
        const auto& droplet = static_cast<const Sphere&>(*document.shape(id));
        EXPECT_EQ(droplet.mediumId(), 1u);
        EXPECT_EQ(hitFrom(document, droplet.center(), Eigen::Vector3d::UnitX()), id);  // from inside it
    }
    const Sphere first = static_cast<const Sphere&>(*document.shape(ids.front()));
    document.undo();
    EXPECT_EQ(document.shapeCount(), 3u);
    EXPECT_EQ(sceneToJson(document.toScene()), before.text);
    document.redo();
    EXPECT_EQ(document.shapeCount(), 403u);
    EXPECT_EQ(static_cast<const Sphere&>(*document.shape(ids.front())).center(), first.center());
}

TEST(SceneDocument, ACloudThatDoesNotFitIsRefusedWhole) {
    SceneDocument document(smallScene());
    DropletCloudSpec spec;
    spec.region = Eigen::AlignedBox3d(Point(20, 20, 20), Point(21, 21, 21));
    spec.count = 1000;
    spec.radius = RadiusDistribution::fixed(0.2);
    const Snapshot before(document);
    const std::string message = refusalOf([&] { document.generateCloud(spec, 1); });
    EXPECT_EQ(message.rfind("placed ", 0), 0u) << message;
    spec.radius = RadiusDistribution::fixed(0.6);
    EXPECT_EQ(refusalOf([&] { document.generateCloud(spec, 1); }),
              "a droplet of radius 0.6 does not fit in the region (its smallest side is 1)");
    spec.radius = RadiusDistribution::fixed(0.1);
    EXPECT_EQ(refusalOf([&] { document.generateCloud(spec, 7); }), "medium 7 is not defined (3 media)");
    EXPECT_EQ(Snapshot(document), before);
}

TEST(SceneDocument, RenameKeepsNamesUniqueAndUndoes) {
    SceneDocument document(smallScene());
    EXPECT_EQ(refusalOf([&] { document.renameShape(1, "d1"); }), "name \"d1\" is already used by shape 0");
    document.renameShape(1, "big");
    EXPECT_EQ(document.findShape("big"), 1u);
    EXPECT_EQ(document.findShape("d2"), std::nullopt);
    document.undo();
    EXPECT_EQ(document.nameOf(1), "d2");
    EXPECT_EQ(document.findShape("d2"), 1u);
    // A deleted shape's name is free again; undoing the delete takes it back.
    document.removeShape(0);
    document.renameShape(1, "d1");
    EXPECT_EQ(document.findShape("d1"), 1u);
    document.undo();
    document.undo();
    EXPECT_EQ(document.findShape("d1"), 0u);
    EXPECT_EQ(document.nameOf(1), "d2");
}

TEST(SceneDocument, ToSceneRoundTripsThroughTheSceneFile) {
    SceneDocument document(smallScene());
    document.removeShape(0);
    ShapeSpec ellipsoid;
    ellipsoid.kind = ShapeKind::Ellipsoid;
    ellipsoid.center = Point(-3, 0, 0);
    ellipsoid.semiAxes = Eigen::Vector3d(1.0, 0.5, 0.3);
    ellipsoid.rotationAxis = Eigen::Vector3d(1, 1, 0);
    ellipsoid.rotationAngleDeg = 40.0;
    ellipsoid.medium = 2;
    const ShapeId e = document.addShape(ellipsoid, "tilted");
    document.setView(SceneView{Point(6, 2, -4), Point::Zero(), Direction(0, 1, 0), 35.0});

    std::vector<ShapeId> slots;
    const Scene scene = document.toScene(&slots);
    ASSERT_EQ(scene.shapes.size(), 3u);
    EXPECT_EQ(slots, (std::vector<ShapeId>{1, 2, e}));
    EXPECT_EQ(scene.shapeNames, (std::vector<std::string>{"d2", "cell", "tilted"}));
    EXPECT_EQ(scene.explicitShapeCount, 3u);

    const Scene reloaded = parseScene(sceneToJson(scene), "saved.json");
    const SceneDocument again{parseScene(sceneToJson(scene), "saved.json")};
    EXPECT_EQ(sceneToJson(again.toScene()), sceneToJson(reloaded));
    ASSERT_EQ(reloaded.shapes.size(), 3u);
    EXPECT_EQ(reloaded.shapeNames[2], "tilted");
    EXPECT_EQ(reloaded.shapes[2]->kind(), ShapeKind::Ellipsoid);
    EXPECT_EQ(reloaded.shapes[2]->mediumId(), 2u);
    EXPECT_EQ(static_cast<const Sphere&>(*reloaded.shapes[0]).center(), Point(3, 0, 0));
    ASSERT_TRUE(reloaded.view.has_value());
    EXPECT_EQ(reloaded.view->fovDeg, 35.0);
    EXPECT_EQ(reloaded.ambient, 0u);
    EXPECT_EQ(reloaded.media.size(), 3u);
}

}  // namespace
}  // namespace dropscope

namespace dropscope {
namespace {

using namespace test;

// docs/limits.md: an edit may not make a shape unusable, nor the scene's reach over its smallest feature
// exceed kMaxScaleRatio; what was accepted before is still accepted after moves back and forth.
TEST(SceneDocument, EditsBeyondTheLimitsAreRefused) {
    SceneDocument document(smallScene());
    const Snapshot before(document);
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(1e300, 0, 0), 1.0)); }),
              "sphere: its bounds reach 1e+300, beyond the limit 1e+100 on any coordinate (docs/limits.md)");
    EXPECT_EQ(refusalOf([&] { document.modifyShape(0, sphereAt(Point(0, 0, 0), 1e-110)); }),
              "sphere: its volume is 0, not finite and > 0 (docs/limits.md)");
    // The cell reaches 10: a droplet of 1e-11 is 1e12 times smaller; 5e-12 is beyond.
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(-3, -3, 0), 5e-12)); }),
              "sphere: its smallest feature (3 volume / area) 5e-12 mm is 2e+12 times smaller than the scene's "
              "reach 10 mm (its farthest shape, source or detector); the limit is 1e+12, beyond which double "
              "precision cannot tell its surface from its inside (docs/limits.md)");
    EXPECT_EQ(refusalOf([&] { document.modifyShape(1, sphereAt(Point(2e12, 0, 0), 1.0)); })
                  .find("sphere: its "
                        "smallest feature"),
              0u);
    std::vector<Source> sources = document.sources();
    sources[0].origin = Point(0, 0, -1e13);
    EXPECT_NE(refusalOf([&] { document.setSources(sources); }).find("times smaller than the scene's reach 1e+13"),
              std::string::npos);
    EXPECT_EQ(Snapshot(document), before);

    // Far, then back, then a small droplet: each state is within the limit, so each is accepted, although the
    // extremes the document has seen (reach 1e9, feature 1e-3) together would not be.
    document.modifyShape(1, sphereAt(Point(1e9, 0, 0), 1.0));
    document.modifyShape(1, sphereAt(Point(3, 0, 0), 1.0));
    EXPECT_EQ(refusalOf([&] { document.addShape(sphereAt(Point(-3, -3, 0), 1e-3)); }), "accepted");
}

// A droplet cloud generated in the app meets the loader's limits now, not when the saved scene is read again.
TEST(SceneDocument, CloudsBeyondTheLimitsAreRefused) {
    SceneDocument document(smallScene());
    const Snapshot before(document);
    DropletCloudSpec spec;
    spec.count = 10;
    // Inside droplet d1, so the region's own scale (1e-3) lets radii down to 1e-12 through (the generator's 1e-9):
    // 2e-12 is 5e12 times below the scene's reach of 10.
    spec.region = Eigen::AlignedBox3d(Point(0, 0, 0), Point(1e-3, 1e-3, 1e-3));
    spec.radius = RadiusDistribution::fixed(2e-12);
    EXPECT_EQ(refusalOf([&] { document.generateCloud(spec, 1); }),
              "the cloud: its smallest feature (3 volume / area) 2e-12 mm is 5e+12 times smaller than the scene's "
              "reach 10 mm (its farthest shape, source or detector); the limit is 1e+12, beyond which double "
              "precision cannot tell its surface from its inside (docs/limits.md)");
    spec.region = Eigen::AlignedBox3d(Point(1e120, 0, 0), Point(2e120, 1e120, 1e120));
    spec.radius = RadiusDistribution::fixed(1e115);
    EXPECT_EQ(refusalOf([&] { document.generateCloud(spec, 1); }),
              "the region's corners are beyond the limit 1e+100 on any coordinate (docs/limits.md)");
    EXPECT_EQ(Snapshot(document), before);
}

}  // namespace
}  // namespace dropscope
