// The 3D view keeps its picture (ViewportScene): the second frame of a view draws it into an image of its
// own, later frames of that view copy the image, and any change of the view draws it again. The copy must
// be the picture itself, so every image here is compared, pixel for pixel, with a view drawn in every frame.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/Screenshot.hpp"
#include "gui/TraceActions.hpp"
#include "gui/ViewportScene.hpp"
#include "render/OffscreenImage.hpp"
#include "render/TestOctahedron.hpp"
#include "scene/ShapeSpec.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace dropscope::gui::testing {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 200;

class KeptView : public ::testing::Test {
protected:
    // The frame `scene` draws of the app's state, read back.
    snapshot::Image drawn(ViewportScene& scene, int width = kWidth, int height = kHeight) {
        wipe();
        scene.draw(harness_.state(), width, height);
        return view(width, height);
    }
    // Whatever the frame before left is wiped first: a copy that did not happen must show.
    void wipe() {
        const render::GlFunctions& gl = harness_.gl();
        gl.ClearColor(1.0f, 0.0f, 1.0f, 1.0f);
        gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    // The buffer is the harness's size; only the corner drawn is the view: the bottom left one, as the
    // image reads from the top down.
    snapshot::Image view(int width = kWidth, int height = kHeight) {
        const snapshot::Image image = harness_.image();
        snapshot::Image corner{width, height, {}};
        for (int y = image.height - height; y < image.height; ++y) {
            const auto row = image.rgba.begin() + 4 * static_cast<std::ptrdiff_t>(y) * image.width;
            corner.rgba.insert(corner.rgba.end(), row, row + 4 * width);
        }
        return corner;
    }
    void expectFrames(const ViewportScene& scene, std::uint64_t drawnFrames, std::uint64_t copiedFrames) {
        EXPECT_EQ(scene.drawnFrames(), drawnFrames);
        EXPECT_EQ(scene.copiedFrames(), copiedFrames);
    }

    AppHarness harness_{kCloudScene, kWidth, kHeight};
    AppState& state_ = harness_.state();
    ViewportScene kept_{harness_.gl()};
    ViewportScene redrawn_{harness_.gl(), false};  // draws its view in every frame
};

TEST_F(KeptView, ASecondFrameOfAViewKeepsItAndLaterFramesCopyTheSamePicture) {
    const snapshot::Image reference = drawn(redrawn_);
    expectFrames(redrawn_, 1, 0);

    EXPECT_EQ(drawn(kept_).rgba, reference.rgba) << "the first frame, drawn straight";
    expectFrames(kept_, 1, 0);
    EXPECT_EQ(drawn(kept_).rgba, reference.rgba) << "the second, drawn into the kept image and copied out";
    expectFrames(kept_, 2, 0);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(drawn(kept_).rgba, reference.rgba) << "copied, frame " << k;
    expectFrames(kept_, 2, 3);
    EXPECT_EQ(drawn(redrawn_).rgba, reference.rgba);
    expectFrames(redrawn_, 2, 0);
}

TEST_F(KeptView, EveryChangeOfTheViewDrawsItAgain) {
    for (int k = 0; k < 3; ++k) drawn(kept_);
    expectFrames(kept_, 2, 1);
    const snapshot::Image before = drawn(kept_);
    expectFrames(kept_, 2, 2);

    // After each change the frame must agree with the view drawn afresh (and differ from the picture kept
    // before, but for the turn back), and the frames after it keep and copy it again.
    std::uint64_t drawnFrames = 2;
    std::uint64_t copiedFrames = 2;
    const auto changed = [&](const char* what, int width = kWidth, int height = kHeight, bool differs = true) {
        const snapshot::Image after = drawn(kept_, width, height);
        EXPECT_EQ(after.rgba != before.rgba, differs) << what;
        EXPECT_EQ(after.rgba, drawn(redrawn_, width, height).rgba) << what;
        EXPECT_EQ(drawn(kept_, width, height).rgba, after.rgba) << what << ", its second frame";
        EXPECT_EQ(drawn(kept_, width, height).rgba, after.rgba) << what << ", copied";
        drawnFrames += 2;
        copiedFrames += 1;
        expectFrames(kept_, drawnFrames, copiedFrames);
    };

    const render::Camera camera = state_.view.camera;
    state_.view.camera.orbit(0.2, 0.0);
    changed("the camera turned");
    state_.view.camera = camera;
    changed("the camera turned back", kWidth, kHeight, false);  // the first view: kept no longer, so drawn
    state_.view.layers.render.background = {0.5f, 0.2f, 0.1f, 1.0f};
    changed("the background");
    state_.scene.selectShape(0);
    changed("a droplet selected");
    changed("another width", kWidth / 2, kHeight);
    changed("another height", kWidth / 2, kHeight / 2);
    // Back to the whole size: the picture kept at the smaller one must not be copied into it.
    const snapshot::Image whole = drawn(kept_);
    EXPECT_EQ(whole.rgba, drawn(redrawn_).rgba);
    ++drawnFrames;
    expectFrames(kept_, drawnFrames, copiedFrames);
}

TEST_F(KeptView, AViewLeftForOneFrameAndComeBackToIsCopiedStill) {
    for (int k = 0; k < 3; ++k) drawn(kept_);
    expectFrames(kept_, 2, 1);
    const snapshot::Image first = drawn(redrawn_);

    const render::Camera camera = state_.view.camera;
    state_.view.camera.orbit(0.2, 0.0);
    EXPECT_NE(drawn(kept_).rgba, first.rgba);  // drawn straight: the image still holds the first view
    expectFrames(kept_, 3, 1);
    state_.view.camera = camera;
    EXPECT_EQ(drawn(kept_).rgba, first.rgba);
    expectFrames(kept_, 3, 2);

    // So is a view a screenshot of another size came between.
    const snapshot::Image small = renderViewport(harness_.gl(), kept_, state_, kWidth / 2, kHeight / 2);
    EXPECT_EQ(small.rgba, renderViewport(harness_.gl(), redrawn_, state_, kWidth / 2, kHeight / 2).rgba);
    expectFrames(kept_, 4, 2);
    EXPECT_EQ(drawn(kept_).rgba, first.rgba);
    expectFrames(kept_, 4, 3);
}

TEST_F(KeptView, AScreenshotOfTheViewAtItsSizeIsTheViewWhetherCopiedOrNot) {
    const snapshot::Image reference = renderViewport(harness_.gl(), redrawn_, state_, kWidth, kHeight);
    EXPECT_EQ(drawn(kept_).rgba, drawn(redrawn_).rgba);
    // Its second frame (kept_) and a copy, each into the screenshot's own framebuffer, read the right way up.
    EXPECT_EQ(renderViewport(harness_.gl(), kept_, state_, kWidth, kHeight).rgba, reference.rgba);
    EXPECT_EQ(renderViewport(harness_.gl(), kept_, state_, kWidth, kHeight).rgba, reference.rgba);
    expectFrames(kept_, 2, 1);
}

// A new selection alone recolours two instances in place (ViewportScene::recolour); the picture is the one
// a view built afresh draws, for droplets across the cloud (the renderer keeps them in Morton order, not by
// id) and with a slice plane leaving some of them out.
TEST_F(KeptView, ASelectionRecoloursTheViewAsARebuildWould) {
    drawn(kept_);
    const snapshot::Image unselected = drawn(kept_);
    int changed = 0;
    for (const bool sliced : {false, true}) {
        state_.view.slice.enabled = sliced;
        drawn(kept_);
        for (ShapeId id = 3; id < 300; id += 23) {
            state_.scene.selectShape(id);
            const std::uint64_t recolours = kept_.recolours();
            const snapshot::Image recoloured = drawn(kept_);
            EXPECT_EQ(kept_.recolours(), recolours + 1) << "shape " << id;
            ViewportScene rebuilt(harness_.gl(), false);
            EXPECT_EQ(recoloured.rgba, drawn(rebuilt).rgba) << "shape " << id << (sliced ? ", sliced" : "");
            changed += !sliced && recoloured.rgba != unselected.rgba ? 1 : 0;
        }
    }
    EXPECT_GT(changed, 5) << "the selected droplets show";
}

// The same for a box and for two instances of one mesh geometry (Renderer::recolourShape finds them by
// their own lists, not the droplets' order).
TEST_F(KeptView, ASelectedBoxOrMeshIsRecolouredAsARebuildWould) {
    SceneDocument& document = state_.scene.document();
    ShapeSpec box;
    box.kind = ShapeKind::Box;
    box.boxMin = Point(-1.0, 2.5, -1.0);
    box.boxMax = Point(1.0, 3.0, 1.0);
    box.medium = 1;
    std::vector<ShapeId> ids{document.addShape(box)};
    for (const double x : {-3.0, 3.0}) {
        ShapeSpec octahedron;
        octahedron.kind = ShapeKind::Parametric;
        octahedron.general = std::make_shared<test::TestOctahedron>(0.6);
        octahedron.center = Point(x, 0.0, 0.0);
        octahedron.medium = 1;
        ids.push_back(document.addShape(octahedron));
    }
    state_.view.fitRequested = true;
    drawn(kept_);
    const snapshot::Image unselected = drawn(kept_);
    for (const ShapeId id : ids) {
        state_.scene.selectShape(id);
        const std::uint64_t recolours = kept_.recolours();
        const snapshot::Image recoloured = drawn(kept_);
        EXPECT_EQ(kept_.recolours(), recolours + 1) << "shape " << id;
        EXPECT_NE(recoloured.rgba, unselected.rgba) << "shape " << id << " shows selected";
        ViewportScene rebuilt(harness_.gl(), false);
        EXPECT_EQ(recoloured.rgba, drawn(rebuilt).rgba) << "shape " << id;
    }
}

// A ray tree shown or dropped, a layer switched or a source moved rebuilds the layers and keeps the shapes'
// instances (not uploaded again), for the picture a view built afresh draws; a droplet moved or the slice plane
// switched on uploads them again.
TEST_F(KeptView, TracesShownOrDroppedKeepTheShapesAsTheyWere) {
    SceneDocument& document = state_.scene.document();
    document.setSources({Source{SourceType::Ray, Point(0.1, 0.05, -5.0), Direction(0.0, 0.0, 1.0), 0.0}});
    const snapshot::Image before = drawn(kept_);
    const std::uint64_t uploads = kept_.shapeUploads();
    fireRayTree(state_);  // on the UI thread: 300 shapes
    ASSERT_TRUE(state_.traces.rayTree);
    const std::uint64_t rebuilds = kept_.rebuilds();
    const snapshot::Image withTree = drawn(kept_);
    EXPECT_EQ(kept_.rebuilds(), rebuilds + 1);
    EXPECT_EQ(kept_.shapeUploads(), uploads);
    EXPECT_NE(withTree.rgba, before.rgba) << "the tree shows";
    ViewportScene rebuilt(harness_.gl(), false);
    EXPECT_EQ(withTree.rgba, drawn(rebuilt).rgba);

    forgetTraces(state_.traces);
    EXPECT_EQ(drawn(kept_).rgba, before.rgba);
    EXPECT_EQ(kept_.shapeUploads(), uploads);

    const ShapeSpec described = describeShape(*document.shape(7));
    document.modifyShape(7, withCenter(described, described.center + Point(0.3, 0.0, 0.0)));
    const snapshot::Image edited = drawn(kept_);
    EXPECT_EQ(kept_.shapeUploads(), uploads + 1);
    ViewportScene afresh(harness_.gl(), false);
    EXPECT_EQ(edited.rgba, drawn(afresh).rgba);

    // A layer switched, or the source moved, keeps them; the slice plane, which drops droplets, does not.
    state_.view.layers.axes = !state_.view.layers.axes;
    std::vector<Source> sources = document.sources();
    sources[0].origin = Point(0.2, 0.0, -5.0);
    document.setSources(sources);
    const snapshot::Image switched = drawn(kept_);
    EXPECT_EQ(kept_.shapeUploads(), uploads + 1);
    ViewportScene switchedAfresh(harness_.gl(), false);
    EXPECT_EQ(switched.rgba, drawn(switchedAfresh).rgba);
    state_.view.slice.enabled = true;
    const snapshot::Image sliced = drawn(kept_);
    EXPECT_EQ(kept_.shapeUploads(), uploads + 2);
    ViewportScene slicedAfresh(harness_.gl(), false);
    EXPECT_EQ(sliced.rgba, drawn(slicedAfresh).rgba);
    EXPECT_NE(sliced.rgba, switched.rgba);
}

TEST_F(KeptView, ACopyIgnoresTheScissorAndLeavesItAsItWas) {
    const snapshot::Image reference = drawn(kept_);
    drawn(kept_);
    const render::GlFunctions& gl = harness_.gl();
    wipe();
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(0, 0, 10, 10);
    kept_.draw(state_, kWidth, kHeight);
    expectFrames(kept_, 2, 1);
    EXPECT_EQ(gl.IsEnabled(GL_SCISSOR_TEST), GL_TRUE);
    GLint box[4] = {};
    gl.GetIntegerv(GL_SCISSOR_BOX, box);
    EXPECT_EQ(box[2], 10);
    gl.Disable(GL_SCISSOR_TEST);
    EXPECT_EQ(view().rgba, reference.rgba);
}

TEST_F(KeptView, AnImageTheDriverCannotMakeLeavesTheFramebufferBoundBefore) {
    const render::GlFunctions& gl = harness_.gl();
    render::OffscreenImage target(gl);
    ASSERT_TRUE(target.bindForDrawing(kWidth, kHeight));
    GLint before = 0;
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &before);
    ASSERT_NE(before, 0);
    GLint largest = 0;
    gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
    render::OffscreenImage tooLarge(gl);
    EXPECT_FALSE(tooLarge.bindForDrawing(largest + 1, 1));
    GLint draw = 0;
    GLint read = 0;
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    EXPECT_EQ(draw, before);
    EXPECT_EQ(read, before);
    EXPECT_EQ(gl.GetError(), static_cast<GLenum>(GL_NO_ERROR));
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(KeptView, TheAppCopiesItsViewWhileNothingInItChanges) {
    const ViewportScene& view = harness_.app().viewport();
    state_.view.camera.orbit(0.1, 0.0);
    harness_.frame();
    const snapshot::Image drawnStraight = harness_.image();
    harness_.frame();
    EXPECT_EQ(harness_.image().rgba, drawnStraight.rgba) << "the frame that keeps the view";
    const std::uint64_t drawnFrames = view.drawnFrames();
    const std::uint64_t copiedFrames = view.copiedFrames();
    harness_.frames(4);
    EXPECT_EQ(harness_.image().rgba, drawnStraight.rgba) << "a frame that copies it";
    EXPECT_EQ(view.drawnFrames(), drawnFrames);
    EXPECT_EQ(view.copiedFrames(), copiedFrames + 4);

    state_.view.camera.orbit(0.1, 0.0);  // what a drag does between frames
    harness_.frame();
    state_.view.camera.orbit(0.1, 0.0);
    harness_.frame();
    EXPECT_EQ(view.drawnFrames(), drawnFrames + 2);
    EXPECT_EQ(view.copiedFrames(), copiedFrames + 4);
}

}  // namespace
}  // namespace dropscope::gui::testing
