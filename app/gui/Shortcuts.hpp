#pragma once

#include "gui/AppState.hpp"

#include <string_view>
#include <vector>

namespace dropscope::gui {

// One keyboard shortcut: the Help window lists this table and handleShortcuts runs it, so the two
// cannot disagree. `run` is null for the keys the viewport handles itself (they need the cursor).
struct Shortcut {
    int key;  // a Key index (InputFrame.hpp)
    bool ctrl;
    bool shift;
    std::string_view keys;  // as the Help window shows it
    std::string_view action;
    void (*run)(AppState&);
};

const std::vector<Shortcut>& shortcuts();
// Mouse gestures of the viewport, for the Help window: {gesture, action}.
const std::vector<std::pair<std::string_view, std::string_view>>& mouseGestures();

// Runs the shortcuts pressed this frame, unless a text field has the keyboard.
void handleShortcuts(AppState& state);

}  // namespace dropscope::gui
