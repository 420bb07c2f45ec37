#include "gui/platform/FramePacing.hpp"

namespace dropscope::gui {

namespace {

// The same state of the window, mouse and keyboard, and nothing typed or scrolled since.
bool unchanged(const InputFrame& before, const InputFrame& now) {
    return now.characters.empty() && now.wheelX == 0.0f && now.wheelY == 0.0f &&
           now.windowWidth == before.windowWidth && now.windowHeight == before.windowHeight &&
           now.framebufferWidth == before.framebufferWidth && now.framebufferHeight == before.framebufferHeight &&
           now.mouseInside == before.mouseInside && now.mouseX == before.mouseX && now.mouseY == before.mouseY &&
           now.mouseDown == before.mouseDown && now.keysDown == before.keysDown && now.ctrl == before.ctrl &&
           now.shift == before.shift && now.alt == before.alt && now.super == before.super;
}

}  // namespace

void FramePacing::frameDrawn(const InputFrame& input, bool busy) {
    const bool quiet = last_ && unchanged(*last_, input) && busy == busy_;
    quietFrames_ = quiet ? quietFrames_ + 1 : 0;
    busy_ = busy;
    last_ = input;
}

double FramePacing::waitSeconds() const {
    if (quietFrames_ < kQuietFrames) return 0.0;
    return busy_ ? kBusyRefreshSeconds : kIdleRefreshSeconds;
}

}  // namespace dropscope::gui
