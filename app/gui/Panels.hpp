#pragma once

#include "gui/AppState.hpp"

namespace dropscope::gui {

// One function a panel (house style: one file each), named by its file. Each reads and edits the parts
// of the state it shows (the whole state when it spans several); edits of the scene go through the
// document, so every one of them is undoable.
void drawMainMenu(AppState& state);
// Shapes, the selected shape's editor, add, droplet cloud.
void drawScenePanel(AppState& state);
// Media, and the Dispersion window of one of them.
void drawMediaPanel(SceneDocument& document, UiState& ui);
// Placement mode and plane, slice plane.
void drawPlacementPanel(PlacementState& placement, SliceSettings& slice, const SceneDocument& document);
// Sources, fire, progress.
void drawFirePanel(AppState& state);
// Detectors: list, add, remove, every field; shown while the detectors layer is on.
void drawDetectorsPanel(AppState& state);
// Levels, statistics, traversal.
void drawOctreePanel(AppState& state);
// The path colouring, the recorded photons and their events with their polarisation.
void drawPathPanel(render::LayerOptions& layers, TraceState& traces, const ItemProbe& probe);
// Fractions, the energy budget, the ray orders and the detectors; the angular distribution and the orders in
// their plot windows, the budget in its window.
void drawResultsPanel(TraceState& traces, UiState& ui);
// Each plane and far-field detector's image in its own window, while open (DetectorWindows.cpp).
void drawDetectorWindows(TraceState& traces, const ItemProbe& probe);
// Open, save as, export, screenshot.
void drawFilePrompts(AppState& state);
void drawHelpWindow(UiState& ui);
void drawStatusBar(AppState& state);

}  // namespace dropscope::gui
