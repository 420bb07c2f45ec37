#pragma once

#include "gui/AppState.hpp"

namespace dropscope::gui {

// One function a panel (house style: one file each). Each reads and edits the parts of the state it
// shows (all of it, when it spans several); edits of the scene go through the document, so every one of
// them is undoable.
void drawMainMenu(AppState& state);
void drawScenePanel(AppState& state);                              // ScenePanel.cpp: shapes, selected shape, add, cloud
void drawMediaPanel(SceneDocument& document, StatusLine& status);  // MediaPanel.cpp
// PlacementPanel.cpp: placement mode and plane, slice plane.
void drawPlacementPanel(PlacementState& placement, SliceSettings& slice, const SceneDocument& document);
void drawFirePanel(AppState& state);     // FirePanel.cpp: sources, fire, progress
void drawOctreePanel(AppState& state);   // OctreePanel.cpp: levels, statistics, traversal
void drawPathPanel(AppState& state);     // PathPanel.cpp: photons and their events
void drawResultsPanel(AppState& state);  // ResultsPanel.cpp: fractions, angular distribution
void drawFilePrompts(AppState& state);   // FilePrompts.cpp: open, save as, export, screenshot
void drawHelpWindow(UiState& ui);        // HelpWindow.cpp
void drawStatusBar(AppState& state);     // StatusBar.cpp

}  // namespace dropscope::gui
