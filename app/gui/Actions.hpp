#pragma once

#include "gui/AppState.hpp"

#include <chrono>
#include <filesystem>

namespace dropscope::gui {

// The things a user can do, shared by the menus, the panels' buttons and the keyboard shortcuts. Each
// reports what it did, or why it could not, in the status line; none throws.

void undo(AppState& state);
void redo(AppState& state);
void deleteSelected(AppState& state);
// Adds a droplet of the placement radius and medium centred at `centre`; refused (status line) when it
// would overlap a shape.
bool placeDroplet(AppState& state, const Point& centre);

// Starts the Monte Carlo trace of the fire settings off the UI thread; the last result stays shown
// until the new one arrives.
void fireTrace(AppState& state);
// The same, started by "live" after a change: nothing said in the status line unless it fails.
void fireTraceAutomatically(AppState& state);
void cancelTrace(AppState& state);
// Traces the selected source's central ray as a ray tree (both branches at every interface).
void fireRayTree(AppState& state);
// Takes a finished trace from the job; traces again when the scene changed under a live trace.
void updateTraces(AppState& state);

// The medium new droplets get: the first that is not the ambient (else the ambient).
MediumId firstDropletMedium(const SceneDocument& document);

// Selects photon `path`'s event `event` (clamped), and the octree traversal of the segment from it.
void selectEvent(AppState& state, int path, int event);
void stepEvent(AppState& state, int delta);

bool openScene(AppState& state, const std::filesystem::path& file);
bool saveScene(AppState& state, const std::filesystem::path& file);
bool exportPaths(AppState& state, const std::filesystem::path& file);

// "dropscope-YYYYMMDD-HHMMSS.png" in `directory` (local time), with "-2", "-3", ... when taken.
std::filesystem::path timestampedScreenshotPath(const std::filesystem::path& directory,
                                                std::chrono::system_clock::time_point when);

}  // namespace dropscope::gui
