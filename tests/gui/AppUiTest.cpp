#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "geometry/Sphere.hpp"
#include "gui/Actions.hpp"
#include "gui/TraceActions.hpp"
#include "render/RayTreeLayer.hpp"
#include "run/TraceRun.hpp"
#include "scene/ShapeSpec.hpp"
#include "snapshot/Image.hpp"
#include "transport/Emission.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/TallyExpectations.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <numbers>
#include <thread>

namespace dropscope::gui::testing {
namespace {

// Positions computed twice in double precision (the app's picking and the closed form here).
constexpr double kPositionRounding = 1e-9;
// Drags go through float mouse coordinates (ImGui's): a few float roundings of ~1000-pixel values.
constexpr double kMouseRounding = 1e-6;
// A drawn droplet differs from the background by far more than this, summed over R, G and B (the
// background is (20, 23, 28); the darkest lit water is above 60 in blue alone).
constexpr int kBackgroundDifference = 60;

// Looking straight down -y from 10 above the origin, +x to the right and -z up the screen, so a point
// (x, 0, z) is at pixel (640 + 640 x / (10 tanX), 400 + 400 z / (10 tanY)).
constexpr const char* kTopDownScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "name": "d1", "center": [2, 0, 2], "radius": 0.5, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]}],
  "view": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}
})";

const double kTanY = std::tan(20.0 * std::numbers::pi / 180.0);
const double kTanX = kTanY * 1280.0 / 800.0;

// The world point on y = 0 under pixel (px, py) of the top-down view, in closed form.
Point topDownPoint(double px, double py) {
    return Point(10.0 * kTanX * (2.0 * px / 1280.0 - 1.0), 0.0, -10.0 * kTanY * (1.0 - 2.0 * py / 800.0));
}
std::pair<float, float> topDownPixel(const Point& p) {
    return {static_cast<float>(640.0 * (1.0 + p.x() / (10.0 * kTanX))),
            static_cast<float>(400.0 * (1.0 + p.z() / (10.0 * kTanY)))};
}

bool differsFromBackground(const snapshot::Image& image, float x, float y) {
    const std::uint8_t* p = image.pixel(static_cast<int>(x), static_cast<int>(y));
    return std::abs(p[0] - 20) + std::abs(p[1] - 23) + std::abs(p[2] - 28) > kBackgroundDifference;
}

const Sphere& sphereAt(AppHarness& harness, ShapeId id) {
    const Shape* shape = harness.state().scene.document().octree().shape(id);
    EXPECT_NE(shape, nullptr);
    EXPECT_EQ(shape->kind(), ShapeKind::Sphere);
    return static_cast<const Sphere&>(*shape);
}

// Over OSMesa's llvmpipe (a software OpenGL) the app draws a view of droplets and paths on the processor, the same
// window as OpenGL draws but for a few pixels at line ends; switched off (View menu) or with a box in the scene,
// OpenGL draws it.
TEST(AppUi, OverASoftwareOpenGLAViewOfDropletsIsDrawnOnTheProcessor) {
    {
        AppHarness harness(kCloudScene);
        ASSERT_TRUE(harness.state().view.layers.render.processorRaster);
        harness.state().view.layers.octree = true;  // lines too
        harness.frames(2);
        EXPECT_TRUE(harness.app().viewport().lastViewOnProcessor());
        const snapshot::Image onProcessor = harness.image();
        harness.state().view.layers.render.processorRaster = false;
        harness.frames(2);
        EXPECT_FALSE(harness.app().viewport().lastViewOnProcessor());
        const snapshot::Image byOpenGL = harness.image();
        int differing = 0;
        int drawn = 0;  // in the middle, between the panels
        for (int y = 0; y < byOpenGL.height; ++y) {
            for (int x = 0; x < byOpenGL.width; ++x) {
                const std::uint8_t* a = onProcessor.pixel(x, y);
                const std::uint8_t* b = byOpenGL.pixel(x, y);
                const bool middle = x >= 400 && x < 880 && y >= 40 && y < 760;
                drawn +=
                    middle && differsFromBackground(byOpenGL, static_cast<float>(x), static_cast<float>(y)) ? 1 : 0;
                differing += std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 24 ? 1 : 0;
            }
        }
        EXPECT_GT(drawn, 2000) << "droplets and octree cells drawn between the panels";
        EXPECT_LT(differing, byOpenGL.width * byOpenGL.height / 1000) << "pixels differing between the two";
    }  // one app at a time: ImGui's context is global

    AppHarness boxed(R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "glass": {"n": 1.5}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"},
                 {"type": "box", "min": [2, -1, -1], "max": [3, 1, 1], "medium": "glass"}]})");
    ASSERT_TRUE(boxed.state().view.layers.render.processorRaster);
    boxed.frames(2);
    EXPECT_FALSE(boxed.app().viewport().lastViewOnProcessor());
}

TEST(AppUi, AClickInPlacementModeDropsADropletOnThePlacementPlaneUnderTheCursor) {
    AppHarness harness(kTopDownScene);
    harness.state().placement.radius = 0.3;
    harness.press('P');
    ASSERT_TRUE(harness.state().placement.active);
    harness.click(740.0f, 480.0f);

    ASSERT_EQ(harness.state().scene.document().shapeCount(), 2u);
    const Sphere& droplet = sphereAt(harness, 1);
    const Point expected = topDownPoint(740.0, 480.0);
    EXPECT_NEAR(droplet.center().x(), expected.x(), kPositionRounding);
    EXPECT_EQ(droplet.center().y(), 0.0);  // exactly on the plane
    EXPECT_NEAR(droplet.center().z(), expected.z(), kPositionRounding);
    EXPECT_EQ(droplet.radius(), 0.3);
    EXPECT_EQ(harness.state().scene.document().media()[droplet.mediumId()].name, "water");
    EXPECT_FALSE(harness.state().ui.status.error()) << harness.state().ui.status.text();
    harness.frame();
    EXPECT_TRUE(differsFromBackground(harness.image(), 740.0f, 480.0f));
}

// A pencil at a glass block's edge, where photons are lost, with a droplet before it that is then removed:
// the status bar says the loss as an error and names the block as the document does, though the trace
// numbered it 0 of the shapes left.
TEST(AppUi, LostPhotonsAreSaidInTheStatusBarNamingTheShape) {
    AppHarness harness(R"({
      "dropscope": 1, "ambient": "air",
      "media": {"air": {"n": 1}, "glass": {"n": 1.5}},
      "shapes": [{"type": "sphere", "center": [5, 5, 5], "radius": 0.5, "medium": "glass"},
                 {"type": "box", "name": "block", "min": [-1, -1, -1], "max": [1, 1, 1], "medium": "glass"}],
      "sources": [{"type": "ray", "origin": [-3, -3, 0], "direction": [1, 1, 0]}],
      "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
    })");
    harness.state().scene.document().removeShape(0);
    fire(harness, 20, 0);
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_NE(harness.state().ui.status.text().find(
                  "lost 100 % of the photons (20 of 20), mostly at box edges or vertices, where a surface has no "
                  "normal (undefined_normal: 20); the first, photon 0, on box \"block\" at (-1, -1, 0), "
                  "undefined_normal"),
              std::string::npos)
        << harness.state().ui.status.text();
}

TEST(AppUi, APlacementThatWouldOverlapIsRefusedWithAVisibleMessage) {
    AppHarness harness(kTopDownScene);
    harness.state().placement.radius = 0.3;
    harness.press('P');
    harness.click(740.0f, 480.0f);
    ASSERT_EQ(harness.state().scene.document().shapeCount(), 2u);
    const std::uint64_t revision = harness.state().scene.document().revision();
    const auto [x, y] = topDownPixel(topDownPoint(740.0, 480.0) + Point(0.4, 0.0, 0.0));  // 0.4 < 0.3 + 0.3
    harness.click(x, y);
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 2u);
    EXPECT_EQ(harness.state().scene.document().revision(), revision);
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_NE(harness.state().ui.status.text().find("overlap"), std::string::npos) << harness.state().ui.status.text();
}

TEST(AppUi, AClickOnADropletInPlacementModeDropsTheNewOneTouchingIt) {
    AppHarness harness(kTopDownScene);
    harness.state().placement.radius = 0.2;
    harness.press('P');
    const auto [x, y] = topDownPixel(Point(2.0, 0.0, 2.0));  // the centre of d1, seen from above
    harness.click(x, y);
    ASSERT_EQ(harness.state().scene.document().shapeCount(), 2u);
    const Sphere& droplet = sphereAt(harness, 1);
    const Sphere& below = sphereAt(harness, 0);
    EXPECT_NEAR((droplet.center() - below.center()).norm(), 0.5 + 0.2, kPositionRounding);  // touching
    EXPECT_GT(droplet.center().y(), 0.6);  // on top, towards the camera
}

TEST(AppUi, UndoAndRedoFromTheKeyboard) {
    AppHarness harness(kTopDownScene);
    harness.press('P');
    harness.click(740.0f, 480.0f);
    ASSERT_EQ(harness.state().scene.document().shapeCount(), 2u);
    harness.press('Z', true);
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 1u);
    harness.press('Y', true);
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 2u);
}

TEST(AppUi, ClickingSelectsAndDraggingMovesTheSelectedDropletInOneUndoStep) {
    AppHarness harness(kTopDownScene);
    const auto [x, y] = topDownPixel(Point(2.0, 0.0, 2.0));
    harness.click(x, y);
    ASSERT_EQ(harness.state().scene.selectedShape(), 0u);
    // The drag plane is horizontal through the centre (y = 0), so 64 pixels right is 64/640 of 10 tanX.
    harness.drag(x, y, x + 64.0f, y);
    const Sphere& moved = sphereAt(harness, 0);
    EXPECT_NEAR(moved.center().x(), 2.0 + 0.1 * 10.0 * kTanX, kMouseRounding);
    EXPECT_NEAR(moved.center().z(), 2.0, kMouseRounding);
    // A second drag is a second undo step.
    harness.drag(x + 64.0f, y, x + 64.0f, y + 64.0f);
    EXPECT_NEAR(sphereAt(harness, 0).center().z(), 2.0 + 0.16 * 10.0 * kTanY, kMouseRounding);
    harness.press('Z', true);
    EXPECT_NEAR(sphereAt(harness, 0).center().x(), 2.0 + 0.1 * 10.0 * kTanX, kMouseRounding);
    EXPECT_NEAR(sphereAt(harness, 0).center().z(), 2.0, kMouseRounding);
    harness.press('Z', true);
    EXPECT_EQ(sphereAt(harness, 0).center(), Point(2.0, 0.0, 2.0));
}

TEST(AppUi, DraggingTheSourceHandlesMovesAndAimsTheSource) {
    AppHarness harness(kTopDownScene);
    Source source;
    source.type = SourceType::Ray;
    source.origin = Point(-2.0, 0.0, -1.0);
    source.direction = Direction(1.0, 0.0, 0.0);
    harness.state().scene.document().setSources({source});
    harness.frames(2);
    const double arrow = render::kSourceGlyph * harness.app().viewport().sceneBounds().diagonal().norm();

    const auto [ox, oy] = topDownPixel(source.origin);
    harness.drag(ox, oy, ox + 64.0f, oy);  // 64 pixels right: 0.1 of 10 tanX along +x
    const Point moved = source.origin + Point(0.1 * 10.0 * kTanX, 0.0, 0.0);
    EXPECT_NEAR((harness.state().scene.document().sources()[0].origin - moved).norm(), 0.0, kMouseRounding);
    EXPECT_EQ(harness.state().scene.document().sources()[0].direction.vector(), Eigen::Vector3d::UnitX());
    EXPECT_EQ(harness.state().scene.selectedShape(), RayHit::kNone);  // a handle drag is not a click on a shape

    const auto [ax, ay] = topDownPixel(moved + arrow * Eigen::Vector3d::UnitX());
    harness.drag(ax, ay, ax, ay + 80.0f);  // the tip 80 pixels down: +z by 0.2 of 10 tanY
    const Eigen::Vector3d aimed = Eigen::Vector3d(arrow, 0.0, 0.2 * 10.0 * kTanY).normalized();
    EXPECT_NEAR((harness.state().scene.document().sources()[0].direction.vector() - aimed).norm(), 0.0, kMouseRounding);

    harness.press('Z', true);  // each drag is one undo step
    EXPECT_EQ(harness.state().scene.document().sources()[0].direction.vector(), Eigen::Vector3d::UnitX());
    harness.press('Z', true);
    EXPECT_EQ(harness.state().scene.document().sources()[0].origin, source.origin);
}

// Head on at kAxisScene's first interface Fresnel gives R = ((n - 1) / (n + 1))^2.
const double kHeadOnReflectance = std::pow(0.3337 / 2.3337, 2);
constexpr double kFresnelRounding = 1e-12;

TEST(AppUi, FiringTracesThePhotonsOffTheUiThreadAndShowsTheExpectedPaths) {
    AppHarness harness(kAxisScene);
    harness.state().traces.fire.photons = 500;
    harness.state().traces.fire.paths = 50;
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.waitForTrace());
    const TraceResult& shown = harness.state().traces.trace->outcome.result;
    ASSERT_EQ(shown.paths.size(), 50u);

    // Every recorded photon runs along the axis: emitted at z = -5, meeting surfaces at z = -1 and z = 1.
    for (const PhotonPath& path : shown.paths) {
        ASSERT_GE(path.events.size(), 3u);
        EXPECT_EQ(path.events[0].position, Point(0.0, 0.0, -5.0));
        EXPECT_NEAR(path.events[1].position.z(), -1.0, kPositionRounding);
        EXPECT_NEAR(path.events[1].reflectance, kHeadOnReflectance, kFresnelRounding);
        for (const Event& event : path.events) {
            EXPECT_NEAR(event.position.x(), 0.0, kPositionRounding);
            EXPECT_NEAR(event.position.y(), 0.0, kPositionRounding);
        }
    }
    // The same photons as the engine traces directly with the same settings.
    TraceSettings settings;
    settings.photons = 500;
    settings.paths = 50;
    settings.seed = harness.state().traces.fire.seed;
    const Scene scene = harness.state().scene.document().toScene();
    const TraceResult direct = test::traceStandard(OpticalScene(scene), scene.sources, settings);
    EXPECT_EQ(test::fates(shown), test::fates(direct));
    ASSERT_EQ(shown.paths.size(), direct.paths.size());
    for (std::size_t k = 0; k < shown.paths.size(); ++k) {
        ASSERT_EQ(shown.paths[k].events.size(), direct.paths[k].events.size());
        for (std::size_t e = 0; e < shown.paths[k].events.size(); ++e) {
            EXPECT_EQ(shown.paths[k].events[e].position, direct.paths[k].events[e].position);
        }
    }
    // Paths are drawn: the line layer holds their segments.
    EXPECT_FALSE(harness.app().viewport().layers().lines.empty());
}

TEST(AppUi, TheRayTreeKeySplitsTheRayAtTheFirstSurfaceByFresnel) {
    AppHarness harness(kAxisScene);
    harness.press('R');
    ASSERT_TRUE(harness.state().traces.rayTree.has_value());
    std::vector<double> weights;
    for (const RayTreeNode& node : harness.state().traces.rayTree->nodes) {
        if (node.parent == 0) {
            EXPECT_NEAR(node.event.position.z(), -1.0, kPositionRounding);
            weights.push_back(node.event.weight);
        }
    }
    ASSERT_EQ(weights.size(), 2u);
    std::sort(weights.begin(), weights.end());
    EXPECT_NEAR(weights[0], kHeadOnReflectance, kFresnelRounding);
    EXPECT_NEAR(weights[1], 1.0 - kHeadOnReflectance, kFresnelRounding);
}

// The ray tree shown is the one an optical scene built afresh from the document gives, node for node.
void expectTreeOfTheDocument(AppHarness& harness, const char* when) {
    ASSERT_TRUE(harness.state().traces.rayTree) << when;
    const RayTree& shown = *harness.state().traces.rayTree;
    const SceneDocument& document = harness.state().scene.document();
    const Source& source = document.sources().front();
    RayTreeSettings settings;
    settings.polarisation = harness.state().traces.fire.polarisation;
    const RayTree direct = traceRayTree(OpticalScene(document.toScene()), Ray{source.origin, source.direction}, 1.0,
                                        settings, emittedPolarisation(source, source.direction));
    ASSERT_EQ(shown.nodes.size(), direct.nodes.size()) << when;
    for (std::size_t k = 0; k < direct.nodes.size(); ++k) {
        EXPECT_EQ(shown.nodes[k].event.position, direct.nodes[k].event.position) << when << ", node " << k;
        EXPECT_EQ(shown.nodes[k].event.weight, direct.nodes[k].event.weight) << when << ", node " << k;
    }
}

// Frames until the ray tree's job is done and nothing is left asked of it; whether it came to that.
bool waitForTheRayTreeJob(AppHarness& harness) {
    const TraceState& traces = harness.state().traces;
    for (int k = 0; k < 2000 && (traces.rayTreeJob.running() || traces.rayTreeAsked != TraceState::RayTreeAsked::No);
         ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        harness.frame();
    }
    harness.frame();  // takes the last outcome
    return !traces.rayTreeJob.running() && traces.rayTreeAsked == TraceState::RayTreeAsked::No;
}

// The live ray tree, traced again as the source moves, keeps the optical scene it was traced through until
// something else changes; every tree is the one a scene built from the document then gives.
TEST(AppUi, TheRayTreeKeepsItsOpticalSceneWhileOnlyTheSourceMoves) {
    AppHarness harness(kAxisScene);
    SceneDocument& document = harness.state().scene.document();
    const auto expectTreeOfTheDocument = [&](const char* when) { testing::expectTreeOfTheDocument(harness, when); };
    harness.press('R');
    ASSERT_TRUE(harness.state().traces.rayTreeScene);
    const RayTreeScene* first = harness.state().traces.rayTreeScene.get();
    expectTreeOfTheDocument("fired");

    std::vector<Source> sources = document.sources();
    sources[0].origin = Point(0.3, 0.2, -5.0);
    document.setSources(sources);
    harness.frame();  // live: traced again
    EXPECT_EQ(harness.state().traces.rayTreeScene.get(), first);
    expectTreeOfTheDocument("the source moved");

    ShapeSpec moved;
    moved.center = Point(0.1, 0.0, 0.0);
    moved.medium = 1;
    document.modifyShape(0, moved);
    harness.frame();
    EXPECT_NE(harness.state().traces.rayTreeScene.get(), first);
    EXPECT_EQ(harness.state().traces.rayTreeScene->revision, document.revisionBesidesSources());
    expectTreeOfTheDocument("the droplet moved");

    const RayTreeScene* second = harness.state().traces.rayTreeScene.get();
    Medium water = document.media()[1];
    water.n = 1.5;
    document.setMedium(1, water);
    harness.frame();
    EXPECT_NE(harness.state().traces.rayTreeScene.get(), second);
    expectTreeOfTheDocument("the water's index changed");
}

// The view takes the ray tree's draw order worked out where it was traced while the document's shapes are those it
// went through: its chords are then those the layer finds itself. With "live" off the tree stays when the droplet
// moves, and its chords are then looked for in the droplet as it is now, where there are none.
TEST(AppUi, TheRayTreesChordsAreThoseOfTheDropletsAsTheyAreNow) {
    AppHarness harness(kAxisScene);
    harness.state().traces.fire.live = false;
    harness.press('R');
    harness.frame();
    const TraceState& traces = harness.state().traces;
    ASSERT_TRUE(traces.rayTree && traces.rayTreeDrawOrder);
    const SceneDocument& document = harness.state().scene.document();
    const auto chordsFoundNow = [&] {
        render::LineBatch lines{render::Anchor{}};
        render::LineBatch chords{render::Anchor{}};
        const render::ChordSplit split{document.octree(), chords, &traces.rayTreeScene->slotOfShape};
        render::addRayTree(lines, *traces.rayTree, 1.0, &split);
        return chords.vertices().size();
    };
    const std::size_t chords = harness.app().viewport().layers().chords.vertices().size();
    EXPECT_GT(chords, 4u);
    EXPECT_GT(harness.app().viewport().lastRebuildSeconds(), 0.0);
    EXPECT_EQ(chords, chordsFoundNow());

    // The order the tree came with is the one taken: with its chords flipped, the view's lines are its chords.
    harness.state().traces.rayTreeDrawOrder->chord.flip();
    ++harness.state().traces.shownId;
    harness.frame();
    const std::size_t segments = traces.rayTreeDrawOrder->order.size();
    EXPECT_EQ(harness.app().viewport().layers().chords.vertices().size(), 2 * segments - chords);
    // Still while only the source moves.
    std::vector<Source> sources = document.sources();
    sources[0].origin.x() += 0.05;
    harness.state().scene.document().setSources(sources);
    harness.frame();
    ASSERT_TRUE(traces.rayTree);
    EXPECT_EQ(harness.app().viewport().layers().chords.vertices().size(), 2 * segments - chords);

    ShapeSpec moved;
    moved.center = Point(5.0, 0.0, 0.0);
    moved.medium = 1;
    harness.state().scene.document().modifyShape(0, moved);
    harness.frame();
    ASSERT_TRUE(traces.rayTree);
    EXPECT_EQ(harness.app().viewport().layers().chords.vertices().size(), 0u);
    EXPECT_EQ(chordsFoundNow(), 0u);
}

// A document above TraceState::rayTreeBackgroundShapes has its trees traced on the job (held here by a gate, so
// that it is surely still busy): the frames go on and the app counts as busy; trees asked for meanwhile, by
// "live" after a droplet and the source moved twice and by the user, wait and then make one tree, of the
// document as it is then (the source's last place); the optical scene is kept as on the UI thread; a tree still
// being traced is not shown once the traces are forgotten, nor over a newer tree traced on the UI thread.
TEST(AppUi, TheRayTreeOfALargeDocumentIsTracedBesideTheFrames) {
    AppHarness harness(kAxisScene);
    TraceState& traces = harness.state().traces;
    SceneDocument& document = harness.state().scene.document();
    traces.rayTreeBackgroundShapes = 0;
    harness.press('R');
    ASSERT_TRUE(waitForTheRayTreeJob(harness));
    expectTreeOfTheDocument(harness, "fired");
    EXPECT_NE(harness.state().ui.status.text().find(" events, "), std::string::npos)
        << harness.state().ui.status.text();
    const RayTreeScene* first = traces.rayTreeScene.get();
    ASSERT_NE(first, nullptr);

    std::promise<void> release;
    traces.rayTreeJob.holdNext(release.get_future().share());
    ShapeSpec moved;
    moved.center = Point(0.1, 0.0, 0.0);
    moved.medium = 1;
    document.modifyShape(0, moved);
    harness.frame();  // live: the tree again, its optical scene to be built on the job
    ASSERT_TRUE(traces.rayTreeJob.running());
    EXPECT_TRUE(harness.app().busy());
    std::vector<Source> sources = document.sources();
    for (const Point& origin : {Point(0.3, 0.2, -5.0), Point(-0.2, 0.1, -5.0)}) {
        sources[0].origin = origin;
        document.setSources(sources);
        harness.frame();
        EXPECT_EQ(traces.rayTreeAsked, TraceState::RayTreeAsked::ByLive);
    }
    fireRayTree(harness.state());
    EXPECT_EQ(traces.rayTreeAsked, TraceState::RayTreeAsked::ByUser);
    EXPECT_NE(harness.state().ui.status.text().find("waiting"), std::string::npos) << harness.state().ui.status.text();
    release.set_value();
    ASSERT_TRUE(waitForTheRayTreeJob(harness));
    expectTreeOfTheDocument(harness, "the droplet and the source moved");
    EXPECT_NE(traces.rayTreeScene.get(), first);
    const RayTreeScene* second = traces.rayTreeScene.get();
    sources[0].origin = Point(0.0, 0.3, -5.0);
    document.setSources(sources);
    harness.frame();
    ASSERT_TRUE(waitForTheRayTreeJob(harness));
    expectTreeOfTheDocument(harness, "the source moved again");
    EXPECT_EQ(traces.rayTreeScene.get(), second);

    // A tree traced on the UI thread (the document below the threshold again) while the job holds an older one.
    std::promise<void> releaseOlder;
    traces.rayTreeJob.holdNext(releaseOlder.get_future().share());
    fireRayTree(harness.state());
    ASSERT_TRUE(traces.rayTreeJob.running());
    traces.rayTreeBackgroundShapes = 1000;
    sources[0].origin = Point(0.2, -0.2, -5.0);
    document.setSources(sources);
    fireRayTree(harness.state());
    const std::uint64_t shown = traces.shownId;
    releaseOlder.set_value();
    ASSERT_TRUE(waitForTheRayTreeJob(harness));
    EXPECT_EQ(traces.shownId, shown) << "the job's older tree was shown over the newer one";
    expectTreeOfTheDocument(harness, "traced on the UI thread");

    traces.rayTreeBackgroundShapes = 0;
    std::promise<void> releaseForgotten;
    traces.rayTreeJob.holdNext(releaseForgotten.get_future().share());
    fireRayTree(harness.state());
    ASSERT_TRUE(traces.rayTreeJob.running());
    forgetTraces(traces);
    releaseForgotten.set_value();
    ASSERT_TRUE(waitForTheRayTreeJob(harness));
    EXPECT_FALSE(traces.rayTree);
    EXPECT_FALSE(traces.rayTreeScene);
    EXPECT_FALSE(traces.rayTreeDrawOrder);
}

TEST(AppUi, StepsThroughTheEventsOfASelectedPathWithItsOctreeTraversal) {
    AppHarness harness(kAxisScene);
    harness.state().traces.fire.paths = 5;
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.waitForTrace());
    harness.press(kKeyRight);  // selects the first photon's first event
    EXPECT_EQ(harness.state().traces.selectedPath, 0);
    EXPECT_EQ(harness.state().traces.selectedEvent, 0);
    ASSERT_TRUE(harness.state().traces.traversal.has_value());
    // From the emission the segment's traversal finds the sphere 4 ahead.
    EXPECT_EQ(harness.state().traces.traversal->record.hit.shape, 0u);
    EXPECT_NEAR(harness.state().traces.traversal->record.hit.distance, 4.0, kPositionRounding);
    harness.press(kKeyRight);
    EXPECT_EQ(harness.state().traces.selectedEvent, 1);
}

std::size_t differingPixels(const snapshot::Image& a, const snapshot::Image& b) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < a.rgba.size(); k += 4)
        count += a.rgba[k] != b.rgba[k] || a.rgba[k + 1] != b.rgba[k + 1];
    return count;
}

TEST(AppUi, TheOctreeLevelControlChangesWhichCellsAreDrawn) {
    AppHarness harness(kCloudScene);
    const auto statistics = harness.state().scene.document().octree().statistics();
    ASSERT_GE(statistics.size(), 3u);
    harness.press('C');  // cells on: only level 0
    ASSERT_TRUE(harness.state().view.layers.octree);
    constexpr std::size_t kVerticesPerCell = 24;  // 12 edges
    EXPECT_EQ(harness.app().viewport().layers().lines.vertices().size(), kVerticesPerCell * statistics[0].cells);
    harness.press(']');
    EXPECT_EQ(harness.state().view.layers.octreeFilter.level, 1);
    EXPECT_EQ(harness.app().viewport().layers().lines.vertices().size(), kVerticesPerCell * statistics[1].cells);
    const snapshot::Image level1 = harness.image();
    harness.press(']');
    EXPECT_EQ(harness.app().viewport().layers().lines.vertices().size(), kVerticesPerCell * statistics[2].cells);
    const snapshot::Image level2 = harness.image();
    EXPECT_GT(differingPixels(level1, level2), 1000u);
}

TEST(AppUi, TheSlicePlaneHidesTheDropletsOnItsFarSide) {
    constexpr const char* twoDroplets = R"({
      "dropscope": 1, "media": {"water": {"n": 1.3337}},
      "shapes": [{"type": "sphere", "center": [-1.5, 0, 0], "radius": 0.5, "medium": "water"},
                 {"type": "sphere", "center": [1.5, 0, 0], "radius": 0.5, "medium": "water"}],
      "view": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40}
    })";
    AppHarness harness(twoDroplets);
    const auto [leftX, leftY] = topDownPixel(Point(-1.5, 0.0, 0.0));
    const auto [rightX, rightY] = topDownPixel(Point(1.5, 0.0, 0.0));
    EXPECT_TRUE(differsFromBackground(harness.image(), leftX, leftY));
    EXPECT_TRUE(differsFromBackground(harness.image(), rightX, rightY));
    harness.state().view.slice.axis = 0;
    harness.state().view.slice.offset = 0.0;
    harness.press('L');
    ASSERT_TRUE(harness.state().view.slice.enabled);
    EXPECT_TRUE(differsFromBackground(harness.image(), leftX, leftY));
    EXPECT_FALSE(differsFromBackground(harness.image(), rightX, rightY));
}

class AppScreenshot : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("dropscope-gui-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(directory_);
        std::filesystem::create_directories(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }
    std::filesystem::path directory_;
};

TEST_F(AppScreenshot, F12WritesATimestampedPngOfTheViewAndSaysWhere) {
    AppOptions options;
    options.screenshotDirectory = directory_;
    AppHarness harness(kTopDownScene, 1280, 800, options);
    harness.press(kKeyF12);
    const std::filesystem::path file = harness.state().ui.lastScreenshot;
    ASSERT_FALSE(file.empty()) << harness.state().ui.status.text();
    EXPECT_EQ(file.parent_path(), directory_);
    EXPECT_TRUE(file.filename().string().starts_with("dropscope-"));
    EXPECT_NE(harness.state().ui.status.text().find(file.filename().string()), std::string::npos);
    const snapshot::Image image = snapshot::readPng(file);
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 800);
    const auto [x, y] = topDownPixel(Point(2.0, 0.0, 2.0));
    EXPECT_TRUE(differsFromBackground(image, x, y));
    // Without the panels: the top-left corner, where the Scene panel is, shows the background.
    EXPECT_FALSE(differsFromBackground(image, 40.0f, 200.0f));
}

TEST_F(AppScreenshot, WithPanelsOrAtAChosenSize) {
    AppHarness harness(kTopDownScene);
    harness.state().ui.screenshot = ScreenshotRequest{directory_ / "panels.png", true, 0, 0};
    harness.frame();
    harness.state().ui.screenshot = ScreenshotRequest{directory_ / "large.png", false, 1600, 900};
    harness.frame();
    const snapshot::Image panels = snapshot::readPng(directory_ / "panels.png");
    const snapshot::Image large = snapshot::readPng(directory_ / "large.png");
    EXPECT_EQ(panels.width, 1280);
    EXPECT_EQ(large.width, 1600);
    EXPECT_EQ(large.height, 900);
    EXPECT_GT(differingPixels(panels, harness.image()), 0u + 0u);  // sanity: both are real frames
    // The Scene panel covers the top-left corner in the one with panels.
    const std::uint8_t* panel = panels.pixel(40, 200);
    EXPECT_TRUE(std::abs(panel[0] - 20) + std::abs(panel[1] - 23) + std::abs(panel[2] - 28) > 4);
}

TEST_F(AppScreenshot, AnUnwritableFileIsReportedAndNothingIsLeftBehind) {
    AppHarness harness(kTopDownScene);
    harness.state().ui.screenshot = ScreenshotRequest{directory_ / "missing" / "shot.png", false, 0, 0};
    harness.frame();
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_FALSE(std::filesystem::exists(directory_ / "missing"));
}

TEST_F(AppScreenshot, SavedScenesReloadWithTheEditsAndTheCamera) {
    AppHarness harness(kTopDownScene);
    harness.press('P');
    harness.click(740.0f, 480.0f);
    const std::filesystem::path file = directory_ / "saved.json";
    harness.state().scene.setFile(file);
    harness.press('S', true);
    ASSERT_FALSE(harness.state().ui.status.error()) << harness.state().ui.status.text();
    const Scene reloaded = loadScene(file);
    ASSERT_EQ(reloaded.shapes.size(), 2u);
    EXPECT_EQ(static_cast<const Sphere&>(*reloaded.shapes[1]).center(), sphereAt(harness, 1).center());
    ASSERT_TRUE(reloaded.view.has_value());
    EXPECT_EQ(reloaded.view->eye, Point(0.0, 10.0, 0.0));
}

TEST_F(AppScreenshot, ExportedPathsAreTheTraceFilesJsonLinesOnePerPhoton) {
    AppHarness harness(kAxisScene);
    harness.state().traces.fire.paths = 7;
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.waitForTrace());
    ASSERT_TRUE(exportPaths(harness.state(), directory_ / "paths.jsonl")) << harness.state().ui.status.text();
    std::ifstream in(directory_ / "paths.jsonl");
    std::string line;
    int lines = 0;
    while (std::getline(in, line)) {
        EXPECT_NE(line.find("\"events\""), std::string::npos);
        ++lines;
    }
    EXPECT_EQ(lines, 7);
}

TEST_F(AppScreenshot, ASceneThatDoesNotOpenLeavesTheCurrentOneAndSaysWhy) {
    AppHarness harness(kTopDownScene);
    std::ofstream(directory_ / "bad.json")
        << R"({"dropscope": 1, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})";
    EXPECT_FALSE(openScene(harness.state(), directory_ / "bad.json"));
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_NE(harness.state().ui.status.text().find("shapes[0].radius"), std::string::npos)
        << harness.state().ui.status.text();
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 1u);
    harness.frame();
}

TEST_F(AppScreenshot, OpeningAnotherSceneDropsTheTraceStillRunningOnTheOldOne) {
    AppHarness harness(kCloudScene);
    std::ofstream(directory_ / "other.json") << kTopDownScene;
    harness.state().scene.document().setSources({Source{SourceType::Beam, Point(0, 0, -5), Direction(0, 0, 1), 2.0}});
    harness.state().traces.fire.photons = 50'000'000;  // far longer than this test
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.state().traces.job.running());
    ASSERT_TRUE(openScene(harness.state(), directory_ / "other.json"));
    EXPECT_FALSE(harness.state().traces.job.running());
    harness.frames(3);
    EXPECT_FALSE(harness.state().traces.trace.has_value());
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 1u);
}

// FramePacing lets an idle window sleep unless the app is busy: a trace running, a screenshot due (after its
// delay), a text field being edited.
TEST_F(AppScreenshot, TheAppIsBusyWhileATraceRunsAScreenshotIsDueOrAFieldIsEdited) {
    AppHarness harness(kCloudScene);
    harness.frames(2);
    EXPECT_FALSE(harness.app().busy());
    harness.state().ui.screenshot = ScreenshotRequest{directory_ / "shot.png", false, 0, 0, 2};
    EXPECT_TRUE(harness.app().busy());
    harness.frames(2);
    EXPECT_TRUE(harness.app().busy());
    harness.frame();  // taken in this one
    EXPECT_TRUE(std::filesystem::exists(directory_ / "shot.png"));
    EXPECT_FALSE(harness.app().busy());

    harness.state().scene.document().setSources({Source{SourceType::Beam, Point(0, 0, -5), Direction(0, 0, 1), 2.0}});
    harness.state().traces.fire.photons = 50'000'000;  // far longer than this test
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.state().traces.job.running());
    EXPECT_TRUE(harness.app().busy());
    harness.state().traces.job.cancel();
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);  // a hang check
    while (harness.state().traces.job.running() && std::chrono::steady_clock::now() < end) harness.frame();
    EXPECT_FALSE(harness.state().traces.job.running());
    EXPECT_FALSE(harness.app().busy());

    ASSERT_TRUE(harness.clickItem("wavelength bins", 8.0f));
    EXPECT_TRUE(harness.app().busy());  // the field is being edited
    harness.press(kKeyEnter);
    harness.frames(2);
    EXPECT_FALSE(harness.app().busy());
}

TEST(AppUi, ShortcutsDoNothingWhileAFileDialogIsOpen) {
    AppHarness harness(kTopDownScene);
    const auto [x, y] = topDownPixel(Point(2.0, 0.0, 2.0));
    harness.click(x, y);
    ASSERT_EQ(harness.state().scene.selectedShape(), 0u);
    harness.state().ui.prompt = FilePrompt::Screenshot;
    harness.frame();
    harness.press(kKeyDelete);
    EXPECT_EQ(harness.state().scene.document().shapeCount(), 1u);
    harness.press('P');
    EXPECT_FALSE(harness.state().placement.active);
}

TEST_F(AppScreenshot, ThePanelLayoutIsRememberedInTheIniFile) {
    AppOptions options;
    options.iniFile = directory_ / "imgui.ini";
    {
        AppHarness harness(kTopDownScene, 1280, 800, options);
        harness.frames(2);
    }
    std::ifstream in(options.iniFile);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* panel : {"[Window][Scene]", "[Window][Fire]", "[Window][Octree]", "[Window][Paths]"}) {
        EXPECT_NE(text.find(panel), std::string::npos) << panel;
    }
}

}  // namespace
}  // namespace dropscope::gui::testing
