// The 3D view is rebuilt from a key of its inputs (ViewKey): changing any one of them rebuilds it once,
// in the next frame, and a frame in which none changed does not rebuild it. Nothing marks the view as
// changed by hand, so each input is changed here as directly as possible.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/Actions.hpp"
#include "gui/TraceActions.hpp"
#include "scene/ShapeSpec.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>

namespace dropscope::gui::testing {
namespace {

class ViewRebuild : public ::testing::Test {
protected:
    // The rebuilds of the frame after `change`; the frame after that, with nothing changed, must rebuild
    // nothing.
    std::uint64_t rebuildsAfter(const std::function<void()>& change) {
        const std::uint64_t before = harness_.app().viewport().rebuilds();
        change();
        harness_.frame();
        const std::uint64_t after = harness_.app().viewport().rebuilds();
        harness_.frame();
        EXPECT_EQ(harness_.app().viewport().rebuilds(), after) << "a frame with nothing changed rebuilt the view";
        return after - before;
    }

    AppHarness harness_{kAxisScene};
    AppState& state_ = harness_.state();
};

TEST_F(ViewRebuild, EachInputRebuildsTheViewOnceAndAFrameWithoutChangeNever) {
    EXPECT_EQ(rebuildsAfter([] {}), 0u);

    ShapeSpec droplet;
    droplet.kind = ShapeKind::Sphere;
    droplet.center = Point(3.0, 0.0, 0.0);
    droplet.radius = 0.5;
    droplet.medium = 1;
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.document().addShape(droplet); }), 1u) << "a document edit";
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.document().undo(); }), 1u) << "an undo";
    EXPECT_EQ(rebuildsAfter([&] { state_.view.layers.axes = true; }), 1u) << "a layer option";
    EXPECT_EQ(rebuildsAfter([&] { state_.view.layers.octreeFilter.level = 1; }), 1u) << "the octree filter";
    EXPECT_EQ(rebuildsAfter([&] { state_.view.slice.enabled = true; }), 1u) << "the slice plane switched on";
    EXPECT_EQ(rebuildsAfter([&] { state_.view.slice.offset = 0.5; }), 1u) << "the slice plane moved";
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.selectShape(0); }), 1u) << "a shape selected";
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.selectShape(RayHit::kNone); }), 1u) << "the selection cleared";
    std::vector<Source> sources = state_.scene.document().sources();
    sources.push_back(Source{SourceType::Ray, Point(0, 0, 5), Direction(0, 0, -1), 0.0});
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.document().setSources(sources); }), 1u) << "a source added";
    EXPECT_EQ(rebuildsAfter([&] { state_.scene.selectSource(1); }), 1u) << "another source selected (its handles)";
    // Things the view does not draw change nothing.
    EXPECT_EQ(rebuildsAfter([&] { state_.placement.radius = 0.1; }), 0u) << "the placement radius";
    EXPECT_EQ(rebuildsAfter([&] { state_.traces.fire.photons = 20; }), 0u) << "the photon count";

    // A new trace: the frames while it runs rebuild nothing, the one that shows it rebuilds once.
    const std::uint64_t beforeTrace = harness_.app().viewport().rebuilds();
    harness_.press(kKeySpace);
    ASSERT_TRUE(harness_.waitForTrace());
    EXPECT_EQ(harness_.app().viewport().rebuilds(), beforeTrace + 1) << "a new trace";
    EXPECT_EQ(rebuildsAfter([] {}), 0u);
    EXPECT_EQ(rebuildsAfter([&] { stepEvent(state_.traces, +1); }), 1u) << "a photon event selected";
    EXPECT_EQ(rebuildsAfter([&] { stepEvent(state_.traces, +1); }), 1u) << "the next event";
    EXPECT_EQ(rebuildsAfter([&] { fireRayTree(state_); }), 1u) << "a ray tree";
}

TEST_F(ViewRebuild, OpeningASceneRebuildsTheViewEvenWhenItsRevisionIsTheOldOnes) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("dropscope-view-rebuild-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".json");
    std::ofstream(file) << kAxisScene;
    // Both documents are fresh (revision 0): only which document it is tells them apart.
    ASSERT_EQ(state_.scene.document().revision(), 0u);
    EXPECT_EQ(rebuildsAfter([&] { ASSERT_TRUE(openScene(state_, file)); }), 1u);
    EXPECT_EQ(state_.scene.document().revision(), 0u);
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace dropscope::gui::testing
