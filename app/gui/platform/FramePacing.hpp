#pragma once

#include "gui/platform/InputFrame.hpp"

#include <optional>

namespace dropscope::gui {

// How long the window may sleep before its next frame. A frame is quiet when its input equals the frame's
// before (nothing moved, typed or scrolled, the window the same size), no key or mouse button is held (ImGui
// repeats held keys and +/- buttons frame by frame), and the app's work under way has neither started nor
// ended. After kQuietFrames quiet frames in a row the window waits for an event, waking at least every
// kIdleRefreshSeconds: an idle app leaves the processor alone (on llvmpipe a frame of a large scene takes both
// cores for a tenth of a second). While the app is busy (a trace running, a screenshot due, a text field
// being edited) it wakes every kBusyRefreshSeconds, or twice the last frame's time if that is longer, so the
// progress bar moves and a trace keeps at least half the processor.
class FramePacing {
public:
    static constexpr int kQuietFrames = 3;  // ImGui settles a hover, a popup or an auto-sized panel within two
    static constexpr double kIdleRefreshSeconds = 0.5;
    static constexpr double kBusyRefreshSeconds = 0.05;

    // After each frame: the input it drew, whether the app has work under way (FrameClient::busy), and how
    // long the frame took.
    void frameDrawn(const InputFrame& input, bool busy, double frameSeconds);
    // 0: draw the next frame at once; otherwise wait for an event for at most this many seconds first.
    double waitSeconds() const;

private:
    std::optional<InputFrame> last_;
    int quietFrames_ = 0;
    bool busy_ = false;
    double frameSeconds_ = 0.0;
};

}  // namespace dropscope::gui
