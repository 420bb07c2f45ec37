#pragma once

#include "gui/platform/InputFrame.hpp"

namespace dropscope::gui {

// What a window (GLFW, or the UI tests' OSMesa buffer) drives once per frame: the app takes the frame's
// input, builds its panels and renders into the current framebuffer.
class FrameClient {
public:
    virtual ~FrameClient() = default;
    virtual void frame(const InputFrame& input) = 0;
    // The user asked to quit (menu, shortcut); the window closes after this frame.
    virtual bool quitRequested() const = 0;
    // Work under way that changes what the next frames show (a trace running, a screenshot due, a blinking
    // text cursor): the window keeps drawing while the user is idle (FramePacing).
    virtual bool busy() const { return false; }
};

}  // namespace dropscope::gui
