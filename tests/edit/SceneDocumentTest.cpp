// SceneDocument: edits keep the octree exact and the scene valid, refusals change nothing, undo and
// redo restore every state, ids never change.
#include "edit/SceneDocument.hpp"

#include "geometry/Box.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/SceneWriter.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

namespace dropscope {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Two named water droplets in air, and a glass cell above them.
Scene smallScene() {
    return parseScene(R"({"dropscope": 1, "ambient": "air",
        "media": {"air": {"n": 1.0}, "water": {"n": 1.333, "kappa": 1e-9}, "glass": {"n": 1.5}},
        "shapes": [
          {"type": "sphere", "name": "d1", "center": [0, 0, 0], "radius": 1, "medium": "water"},
          {"type": "sphere", "name": "d2", "center": [3, 0, 0], "radius": 1, "medium": "water"},
          {"type": "box", "name": "cell", "min": [-5, -5, 5], "max": [5, 5, 10], "medium": "glass"}],
        "sources": [{"type": "ray", "origin": [0, 0, -10], "direction": [0, 0, 1]}]})",
                      "small.json");
}

ShapeSpec sphereAt(const Point& center, double radius, MediumId medium = 1) {
    ShapeSpec spec;
    spec.center = center;
    spec.radius = radius;
    spec.medium = medium;
    return spec;
}

// The shape firstHit finds from `origin` along `direction`, or RayHit::kNone.
ShapeId hitFrom(const SceneDocument& document, const Point& origin, const Eigen::Vector3d& direction) {
    return document.octree().firstHit(origin, Direction(direction)).shape;
}

std::string refusalOf(const std::function<void()>& edit) {
    try {
        edit();
    } catch (const EditRefused& refusal) {
        return refusal.what();
    }
    return "accepted";
}

// Everything a refused edit must leave alone.
struct Snapshot {
    std::uint64_t revision;
    std::size_t shapes;
    std::size_t slots;
    std::size_t undo;
    std::size_t redo;
    std::string text;
    explicit Snapshot(const SceneDocument& d)
        : revision(d.revision()), shapes(d.shapeCount()), slots(d.slotCount()), undo(d.undoDepth()),
          redo(d.redoDepth()), text(sceneToJson(d.toScene())) {}
    bool operator==(const Snapshot&) const = default;
};

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
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0, 2, 0), 1.0)));           // touches d1
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0, 0, 7), 1.0)));           // in the cell
    EXPECT_NO_THROW(document.addShape(sphereAt(Point(0.2, 0, 0), 0.5)));         // in d1
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

TEST(SceneDocument, RedoReappliesAndEveryStepBumpsTheRevision) {
    SceneDocument document(smallScene());
    const ShapeId id = document.addShape(sphereAt(Point(-4, 0, 0), 0.5));
    const std::uint64_t afterAdd = document.revision();
    document.undo();
    EXPECT_GT(document.revision(), afterAdd);
    EXPECT_EQ(document.shape(id), nullptr);
    EXPECT_EQ(document.redoLabel(), "add sphere");
    const std::uint64_t afterUndo = document.revision();
    document.redo();
    EXPECT_GT(document.revision(), afterUndo);
    EXPECT_NE(document.shape(id), nullptr);
    EXPECT_EQ(hitFrom(document, Point(-4, 0, -5), Eigen::Vector3d::UnitZ()), id);
    EXPECT_FALSE(document.canRedo());
    const std::uint64_t now = document.revision();
    document.redo();  // nothing to redo: nothing happens
    EXPECT_EQ(document.revision(), now);
}

TEST(SceneDocument, ANewEditClearsRedo) {
    SceneDocument document(smallScene());
    document.addShape(sphereAt(Point(-4, 0, 0), 0.5));
    document.undo();
    ASSERT_TRUE(document.canRedo());
    document.removeShape(1);
    EXPECT_FALSE(document.canRedo());
    EXPECT_EQ(document.undoDepth(), 1u);
}

TEST(SceneDocument, MergedDragsAreOneUndoStep) {
    SceneDocument document(smallScene());
    document.addShape(sphereAt(Point(-4, 0, 0), 0.5));
    const std::size_t depth = document.undoDepth();
    for (int step = 1; step <= 10; ++step) {
        document.modifyShape(1, sphereAt(Point(3, 0.5 * step, 0), 1.0), step > 1);
    }
    EXPECT_EQ(document.undoDepth(), depth + 1);
    EXPECT_EQ(document.undoLabel(), "move sphere \"d2\"");
    EXPECT_EQ(hitFrom(document, Point(3, 5, -5), Eigen::Vector3d::UnitZ()), 1u);
    document.undo();
    EXPECT_EQ(static_cast<const Sphere&>(*document.shape(1)).center(), Point(3, 0, 0));
    EXPECT_EQ(document.undoLabel(), "add sphere");
    // Merging never reaches into another shape's step.
    document.redo();
    document.modifyShape(0, sphereAt(Point(0, -0.5, 0), 1.0), true);
    EXPECT_EQ(document.undoDepth(), depth + 2);
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

TEST(SceneDocument, MediaEditsValidateComputeAbsorptionAndUndo) {
    SceneDocument document(smallScene());
    const MediumId ink = document.addMedium({"ink", 1.34, {}, 0.5, 0.0});
    EXPECT_EQ(ink, 3u);
    EXPECT_EQ(document.media()[ink].absorptionPerUnit, 0.5);
    EXPECT_EQ(document.undoLabel(), "add medium \"ink\"");
    document.setMedium(1, {"water", 1.33, 2e-9, {}, 0.0});
    // kappa to absorption exactly as the loader does it.
    const Scene loaded = parseScene(R"({"dropscope": 1, "media": {"water": {"n": 1.33, "kappa": 2e-9}}})", "w.json");
    EXPECT_EQ(document.media()[1].absorptionPerUnit, loaded.media[0].absorptionPerUnit);
    EXPECT_GT(document.media()[1].absorptionPerUnit, 0.0);

    const Snapshot before(document);
    EXPECT_EQ(refusalOf([&] { document.addMedium({"", 1.0, {}, {}, 0.0}); }), "a medium name must not be empty");
    EXPECT_EQ(refusalOf([&] { document.addMedium({"glass", 1.0, {}, {}, 0.0}); }),
              "medium name \"glass\" is already used");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", 0.0, {}, {}, 0.0}); }), "n must be finite and > 0");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", kNan, {}, {}, 0.0}); }), "n must be finite and > 0");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", 1.3, 1e-9, 0.1, 0.0}); }),
              "give either kappa or sigma, not both");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", 1.3, -1e-9, {}, 0.0}); }),
              "kappa must be finite and >= 0");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", 1.3, {}, -1.0, 0.0}); }),
              "sigma must be finite and >= 0");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"air", 1.3, {}, {}, 0.0}); }),
              "medium name \"air\" is already used");
    EXPECT_EQ(refusalOf([&] { document.setMedium(9, {"x", 1.3, {}, {}, 0.0}); }), "medium 9 is not defined (4 media)");
    EXPECT_EQ(refusalOf([&] { document.setAmbient(9); }), "medium 9 is not defined (4 media)");
    EXPECT_EQ(Snapshot(document), before);

    document.setAmbient(ink);
    EXPECT_EQ(document.ambient(), ink);
    document.undo();
    EXPECT_EQ(document.ambient(), 0u);
    document.undo();
    EXPECT_EQ(document.media()[1].n, 1.333);
    EXPECT_EQ(document.media()[1].kappa, 1e-9);
    document.undo();
    EXPECT_EQ(document.media().size(), 3u);
}

TEST(SceneDocument, SourceEditsValidateAndUndo) {
    SceneDocument document(smallScene());
    Source beam;
    beam.type = SourceType::Beam;
    beam.origin = Point(0, 0, -20);
    beam.direction = Direction(0, 0, 1);
    beam.radius = 2.0;
    document.setSources({beam});
    EXPECT_EQ(document.sources().size(), 1u);
    EXPECT_EQ(document.sources()[0].type, SourceType::Beam);
    Source bad = beam;
    bad.radius = 0.0;
    EXPECT_EQ(refusalOf([&] { document.setSources({beam, bad}); }), "source 1: beam radius must be finite and > 0");
    bad = beam;
    bad.direction = Direction(0, 0, 0);
    EXPECT_EQ(refusalOf([&] { document.setSources({bad}); }), "source 0: direction must be a finite, non-zero vector");
    document.undo();
    EXPECT_EQ(document.sources()[0].type, SourceType::Ray);
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

TEST(SceneDocument, HistoryIsCapped) {
    SceneDocument document(smallScene());
    for (std::size_t i = 0; i < SceneDocument::kMaxUndoSteps + 20; ++i) {
        document.modifyShape(1, sphereAt(Point(3, 0.01 * static_cast<double>(i), 0), 1.0));
    }
    EXPECT_EQ(document.undoDepth(), SceneDocument::kMaxUndoSteps);
    while (document.canUndo()) document.undo();
    EXPECT_EQ(static_cast<const Sphere&>(*document.shape(1)).center(), Point(3, 0.01 * 19, 0));
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

// A random sequence of edits, undos and redos; after each batch the octree answers random rays exactly
// as a fresh octree over toScene()'s shapes (ids mapped through slotOfShape).
TEST(SceneDocument, RandomEditsKeepTheOctreeExact) {
    for (int c = 0; c < 4; ++c) {
        SCOPED_TRACE("case " + std::to_string(c));
        testing::Rng rng(static_cast<std::uint64_t>(c));
        SceneDocument document(smallScene());
        int accepted = 0;
        for (int step = 0; step < 240; ++step) {
            const auto live = [&] {
                std::vector<ShapeId> ids;
                for (ShapeId id = 0; id < document.slotCount(); ++id) {
                    if (document.shape(id)) ids.push_back(id);
                }
                return ids;
            }();
            const double size = testing::uniform(rng, 0.1, 1.0);
            ShapeSpec spec = describeShape(*testing::randomShape(rng, step, testing::randomPoint(rng, 12.0), size));
            spec.medium = 1;
            try {
                switch (rng() % 8) {
                    case 0: case 1: case 2: document.addShape(spec); break;
                    case 3: if (!live.empty()) document.removeShape(live[rng() % live.size()]); break;
                    case 4: case 5:
                        if (!live.empty()) document.modifyShape(live[rng() % live.size()], spec, rng() % 2 == 0);
                        break;
                    case 6: document.undo(); break;
                    default: document.redo(); break;
                }
                ++accepted;
            } catch (const EditRefused&) {
            }
            if (step == 120) {  // a cloud in the middle of it all
                DropletCloudSpec cloud;
                cloud.region = Eigen::AlignedBox3d(Point(-12, -12, -12), Point(12, 12, 12));
                cloud.count = 60;
                cloud.radius = RadiusDistribution::uniform(0.05, 0.3);
                cloud.seed = static_cast<std::uint64_t>(c);
                ASSERT_EQ(document.generateCloud(cloud, 1).size(), 60u);
            }
            if (step % 40 != 39) continue;
            std::vector<ShapeId> slots;
            Scene scene = document.toScene(&slots);
            ASSERT_EQ(scene.shapes.size(), document.shapeCount());
            EXPECT_NO_THROW(checkShapesDisjoint(scene));
            const Octree fresh(std::move(scene.shapes), scene.octree);
            for (int r = 0; r < 400; ++r) {
                const Point origin = testing::randomPoint(rng, 16.0);
                const Direction d = testing::randomDirection(rng);
                const RayHit expected = fresh.firstHit(origin, d);
                const RayHit actual = document.octree().firstHit(origin, d);
                ASSERT_EQ(actual.shape, expected ? slots[expected.shape] : RayHit::kNone)
                    << "step " << step << " ray " << r;
                if (expected) {
                    ASSERT_EQ(actual.distance, expected.distance);
                }
            }
        }
        EXPECT_GT(accepted, 100);
    }
}

}  // namespace
}  // namespace dropscope
