#include "gui/platform/FramePacing.hpp"

#include <algorithm>

namespace dropscope::gui {

namespace {

// The same state of the window, mouse and keyboard, nothing held, and nothing typed or scrolled since.
bool unchanged(const InputFrame& before, const InputFrame& now) {
    const bool held = now.keysDown.any() || now.mouseDown[0] || now.mouseDown[1] || now.mouseDown[2];
    return !held && now.characters.empty() && now.wheelX == 0.0f && now.wheelY == 0.0f &&
           now.windowWidth == before.windowWidth && now.windowHeight == before.windowHeight &&
           now.framebufferWidth == before.framebufferWidth && now.framebufferHeight == before.framebufferHeight &&
           now.mouseInside == before.mouseInside && now.mouseX == before.mouseX && now.mouseY == before.mouseY &&
           now.mouseDown == before.mouseDown && now.keysDown == before.keysDown && now.ctrl == before.ctrl &&
           now.shift == before.shift && now.alt == before.alt && now.super == before.super;
}

}  // namespace

void FramePacing::frameDrawn(const InputFrame& input, bool busy, double frameSeconds) {
    const bool quiet = last_ && unchanged(*last_, input) && busy == busy_;
    quietFrames_ = quiet ? quietFrames_ + 1 : 0;
    busy_ = busy;
    frameSeconds_ = frameSeconds;
    last_ = input;
}

double FramePacing::waitSeconds() const {
    if (quietFrames_ < kQuietFrames) return 0.0;
    return busy_ ? std::max(kBusyRefreshSeconds, 2.0 * frameSeconds_) : kIdleRefreshSeconds;
}

}  // namespace dropscope::gui
