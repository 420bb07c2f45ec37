#include "gui/platform/FramePacing.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace dropscope::gui {
namespace {

constexpr int kQuiet = FramePacing::kQuietFrames;

// Frames of `input` until the window may wait; how many it took (kQuiet + 2 if it never may).
int framesUntilWaiting(FramePacing& pacing, const InputFrame& input, bool busy = false, double frameSeconds = 0.01) {
    for (int frames = 1; frames <= kQuiet + 1; ++frames) {
        pacing.frameDrawn(input, busy, frameSeconds);
        if (pacing.waitSeconds() > 0.0) return frames;
    }
    return kQuiet + 2;
}

TEST(FramePacing, AnIdleAppWaitsForEventsAfterAFewQuietFrames) {
    FramePacing pacing;
    EXPECT_EQ(pacing.waitSeconds(), 0.0);
    const InputFrame still;
    EXPECT_EQ(framesUntilWaiting(pacing, still), kQuiet + 1);  // the first frame has nothing to compare with
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kIdleRefreshSeconds);
    pacing.frameDrawn(still, false, 0.01);
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kIdleRefreshSeconds);
}

// Any change of input draws frames at once until it has been still for kQuietFrames frames.
TEST(FramePacing, EveryKindOfInputWakesIt) {
    const std::function<void(InputFrame&)> changes[] = {
        [](InputFrame& f) { f.mouseX += 1.0f; },
        [](InputFrame& f) { f.mouseY -= 1.0f; },
        [](InputFrame& f) { f.mouseInside = !f.mouseInside; },
        [](InputFrame& f) { f.mouseDown[1] = true; },
        [](InputFrame& f) { f.wheelY = 1.0f; },
        [](InputFrame& f) { f.wheelX = -1.0f; },
        [](InputFrame& f) { f.keysDown.set(kKeyF12); },
        [](InputFrame& f) { f.keysDown.set('P'); },
        [](InputFrame& f) { f.ctrl = true; },
        [](InputFrame& f) { f.shift = true; },
        [](InputFrame& f) { f.alt = true; },
        [](InputFrame& f) { f.super = true; },
        [](InputFrame& f) { f.characters.push_back('x'); },
        [](InputFrame& f) { f.windowWidth = 1000; },
        [](InputFrame& f) { f.framebufferHeight = 600; },
    };
    int kind = 0;
    for (const auto& change : changes) {
        FramePacing pacing;
        const InputFrame still;
        framesUntilWaiting(pacing, still);
        ASSERT_GT(pacing.waitSeconds(), 0.0);
        InputFrame changed = still;
        change(changed);
        pacing.frameDrawn(changed, false, 0.01);
        EXPECT_EQ(pacing.waitSeconds(), 0.0) << "change " << kind;
        // Typing and scrolling are events of one frame, after which the input is as still as before; a key or
        // button held keeps it drawing (ImGui repeats them frame by frame); the rest stay as changed, still.
        const bool once = !changed.characters.empty() || changed.wheelX != 0.0f || changed.wheelY != 0.0f;
        const bool held = changed.keysDown.any() || changed.mouseDown[1];
        EXPECT_EQ(framesUntilWaiting(pacing, once ? still : changed), held ? kQuiet + 2 : kQuiet) << "change " << kind;
        ++kind;
    }
}

// The time between frames is not input: a still window waits however long its frames were apart.
TEST(FramePacing, TheTimeBetweenFramesIsNotInput) {
    FramePacing pacing;
    InputFrame still;
    for (int frame = 0; frame <= kQuiet; ++frame) {
        still.deltaSeconds = 0.01 * (frame + 1);
        pacing.frameDrawn(still, false, 0.01);
    }
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kIdleRefreshSeconds);
}

// A scroll or typed text reported frame after frame keeps it drawing.
TEST(FramePacing, ContinuousInputNeverWaits) {
    FramePacing pacing;
    InputFrame scrolling;
    scrolling.wheelY = 1.0f;
    for (int frame = 0; frame < 10; ++frame) {
        pacing.frameDrawn(scrolling, false, 0.01);
        EXPECT_EQ(pacing.waitSeconds(), 0.0);
    }
    InputFrame dragging;
    dragging.mouseDown[0] = true;
    for (int frame = 0; frame < 10; ++frame) {
        dragging.mouseX += 2.0f;
        pacing.frameDrawn(dragging, false, 0.01);
        EXPECT_EQ(pacing.waitSeconds(), 0.0);
    }
}

// Busy: a still window wakes often; work starting or ending counts as a change, so its first frames after are
// drawn at once.
TEST(FramePacing, WorkUnderWayWakesItOftenAndItsEndDrawsAtOnce) {
    FramePacing pacing;
    const InputFrame still;
    framesUntilWaiting(pacing, still);
    pacing.frameDrawn(still, true, 0.01);
    EXPECT_EQ(pacing.waitSeconds(), 0.0);
    EXPECT_EQ(framesUntilWaiting(pacing, still, true), kQuiet);
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kBusyRefreshSeconds);
    pacing.frameDrawn(still, false, 0.01);
    EXPECT_EQ(pacing.waitSeconds(), 0.0);
    EXPECT_EQ(framesUntilWaiting(pacing, still), kQuiet);
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kIdleRefreshSeconds);
}

// Frames slower than half the busy refresh: it waits twice a frame's time, so work under way keeps at least half
// the processor.
TEST(FramePacing, SlowFramesWhileBusyLeaveHalfTheTime) {
    FramePacing pacing;
    const InputFrame still;
    EXPECT_EQ(framesUntilWaiting(pacing, still, true, 0.2), kQuiet + 1);
    EXPECT_DOUBLE_EQ(pacing.waitSeconds(), 0.4);
    pacing.frameDrawn(still, true, 0.001);
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kBusyRefreshSeconds);
    pacing.frameDrawn(still, false, 0.2);
    framesUntilWaiting(pacing, still, false, 0.2);
    EXPECT_EQ(pacing.waitSeconds(), FramePacing::kIdleRefreshSeconds);  // idle: never sooner for slow frames
}

}  // namespace
}  // namespace dropscope::gui
