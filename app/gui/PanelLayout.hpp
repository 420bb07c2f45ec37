#pragma once

#include <imgui.h>

namespace dropscope::gui {

// Where each panel first appears (afterwards ImGui's ini file remembers where the user put it): a
// column on each side of the 3D view, under the menu bar and above the status bar.
inline constexpr float kPanelWidth = 330.0f;
inline constexpr float kMenuHeight = 20.0f;
inline constexpr float kStatusHeight = 26.0f;

// Refusals and errors in the status line and the placement tooltip.
inline const ImVec4 kErrorColour{1.0f, 0.45f, 0.35f, 1.0f};

enum class PanelSide { Left, Right };

// Places the next window in its column, `top` and `height` as fractions of the column's height.
inline void placeNextPanel(PanelSide side, float top, float height) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float column = display.y - kMenuHeight - kStatusHeight;
    const float x = side == PanelSide::Left ? 0.0f : display.x - kPanelWidth;
    ImGui::SetNextWindowPos(ImVec2(x, kMenuHeight + top * column), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, height * column), ImGuiCond_FirstUseEver);
}

}  // namespace dropscope::gui
