#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace dropscope::gui {

// Where a widget was drawn, in ImGui's display coordinates (window pixels), and for a text what it says.
struct ItemRect {
    float minX = 0.0f;
    float minY = 0.0f;
    float maxX = 0.0f;
    float maxY = 0.0f;
    std::string text;
};

// Told, in each frame that draws them, where a few named fields are (the shape editor's "centre"), and
// what a few texts say (a cell of the event table): how the UI tests find a field to click and type into,
// as a user would, and read what is shown, without depending on the panel's layout. The app itself runs
// without one.
using ItemProbe = std::function<void(std::string_view name, const ItemRect& rect)>;

}  // namespace dropscope::gui
