// SceneDocument history: undo and redo restore every state, merged drags, the cap, and a long
// random sequence of edits against a fresh octree.
#include "edit/SceneDocument.hpp"
#include "edit/SceneDocumentTestSupport.hpp"

#include "geometry/RandomGeometry.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneOverlaps.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using namespace test;

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

// What an optical scene is built from stays through source edits, their merged drags, undo and redo; every
// other edit moves it on, a merged shape drag at every step.
TEST(SceneDocument, TheRevisionBesidesSourcesStaysThroughSourceEditsOnly) {
    SceneDocument document(smallScene());
    const auto moved = [&](double x) {
        std::vector<Source> sources = document.sources();
        sources[0].origin = Point(x, 0, -10);
        return sources;
    };
    std::uint64_t revision = document.revision();
    const std::uint64_t besides = document.revisionBesidesSources();
    const auto expectOnlyRevisionMoves = [&] {
        EXPECT_GT(document.revision(), revision);
        EXPECT_EQ(document.revisionBesidesSources(), besides);
        revision = document.revision();
    };
    document.setSources(moved(0.5));
    expectOnlyRevisionMoves();
    document.setSources(moved(0.7), true);  // a drag, merged
    expectOnlyRevisionMoves();
    document.undo();
    expectOnlyRevisionMoves();
    document.redo();
    expectOnlyRevisionMoves();

    std::uint64_t last = besides;
    const auto expectBothMove = [&](const char* edit) {
        EXPECT_GT(document.revision(), revision) << edit;
        EXPECT_GT(document.revisionBesidesSources(), last) << edit;
        revision = document.revision();
        last = document.revisionBesidesSources();
    };
    document.modifyShape(1, sphereAt(Point(3, 0.5, 0), 1.0));
    expectBothMove("move");
    document.modifyShape(1, sphereAt(Point(3, 1.0, 0), 1.0), true);
    expectBothMove("merged move");
    Medium water = document.media()[1];
    water.n = 1.34;
    document.setMedium(1, water);
    expectBothMove("medium");
    Detector absorber = screen("absorber");
    document.addDetector(absorber);
    expectBothMove("detector");
    absorber.center = Point(0, 0, 21);
    document.setDetector(0, absorber, true);
    expectBothMove("merged detector drag");
    document.undo();
    expectBothMove("undo of the detector");
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

TEST(SceneDocument, HistoryIsCapped) {
    SceneDocument document(smallScene());
    for (std::size_t i = 0; i < SceneDocument::kMaxUndoSteps + 20; ++i) {
        document.modifyShape(1, sphereAt(Point(3, 0.01 * static_cast<double>(i), 0), 1.0));
    }
    EXPECT_EQ(document.undoDepth(), SceneDocument::kMaxUndoSteps);
    while (document.canUndo()) document.undo();
    EXPECT_EQ(static_cast<const Sphere&>(*document.shape(1)).center(), Point(3, 0.01 * 19, 0));
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
                case 0:
                case 1:
                case 2: document.addShape(spec); break;
                case 3:
                    if (!live.empty()) document.removeShape(live[rng() % live.size()]);
                    break;
                case 4:
                case 5:
                    if (!live.empty()) document.modifyShape(live[rng() % live.size()], spec, rng() % 2 == 0);
                    break;
                case 6: document.undo(); break;
                default: document.redo(); break;
                }
                ++accepted;
            } catch (const EditRefused&) {}
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

namespace dropscope {
namespace {

TEST(SceneDocument, ADraggedSourceIsOneUndoStepAndAFreshEditIsAnother) {
    SceneDocument document(test::smallScene());
    const std::vector<Source> original = document.sources();
    Source source;
    source.origin = Point(0, 0, -9);
    source.direction = Direction(0, 0, 1);
    document.setSources({source});
    const std::size_t depth = document.undoDepth();
    for (int k = 1; k <= 5; ++k) {
        source.origin = Point(0.1 * k, 0, -9);
        document.setSources({source}, true);
    }
    EXPECT_EQ(document.undoDepth(), depth);
    EXPECT_EQ(document.sources().front().origin, Point(0.5, 0, -9));
    document.undo();
    EXPECT_EQ(document.sources().size(), original.size());
    document.redo();
    EXPECT_EQ(document.sources().front().origin, Point(0.5, 0, -9));
    // A merge never folds into another kind of step.
    document.addShape(test::sphereAt(Point(-4, 0, 0), 0.5));
    source.origin = Point(1, 0, -9);
    document.setSources({source}, true);
    EXPECT_EQ(document.undoDepth(), depth + 2);
}

}  // namespace
}  // namespace dropscope
