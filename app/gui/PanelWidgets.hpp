#pragma once

#include "gui/AppState.hpp"

#include <string_view>

namespace dropscope::gui {

// Widgets more than one panel uses.

// Three doubles in one row (a point, a direction, semi-axes); true when edited this frame.
bool inputVector3(const char* label, Eigen::Vector3d& v, const char* format = "%.6g");
// A choice among the document's media; true when another one was chosen.
bool mediumCombo(const char* label, const SceneDocument& document, MediumId& medium);
// Tells the probe, if there is one, where the last widget was drawn, under `name`.
void reportItemRect(const ItemProbe& probe, std::string_view name);
// The running trace's progress bar (or "building the octree") with its Cancel button, on one line.
void drawTraceProgress(AppState& state, float barWidth);

}  // namespace dropscope::gui
