#pragma once

#include "gui/AppState.hpp"

#include <chrono>
#include <filesystem>

namespace dropscope::gui {

// The things a user does to the scene and its files, shared by the menus, the panels' buttons and the
// keyboard shortcuts (the traces' are in TraceActions.hpp). Each reports what it did, or why it could
// not, in the status line; none throws.

void undo(AppState& state);
void redo(AppState& state);
void deleteSelected(AppState& state);
// Adds a droplet of the placement radius and medium centred at `centre`; refused (status line) when it
// would overlap a shape.
bool placeDroplet(AppState& state, const Point& center);

// The medium new droplets get: the first that is not the ambient (else the ambient).
MediumId firstDropletMedium(const SceneDocument& document);

bool openScene(AppState& state, const std::filesystem::path& file);
bool saveScene(AppState& state, const std::filesystem::path& file);
bool exportPaths(AppState& state, const std::filesystem::path& file);

// "dropscope-YYYYMMDD-HHMMSS.png" in `directory` (local time), with "-2", "-3", ... when taken.
std::filesystem::path timestampedScreenshotPath(const std::filesystem::path& directory,
                                                std::chrono::system_clock::time_point when);

}  // namespace dropscope::gui
