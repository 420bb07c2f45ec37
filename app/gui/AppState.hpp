#pragma once

#include "gui/PlacementState.hpp"
#include "gui/SceneState.hpp"
#include "gui/TraceState.hpp"
#include "gui/UiState.hpp"
#include "gui/ViewState.hpp"

#include <filesystem>
#include <utility>

namespace dropscope::gui {

// What the app keeps between frames, by concern. The App owns one; actions and panels that span
// several concerns take it whole, the others only the parts they read and change.
struct AppState {
    AppState(Scene initial, std::filesystem::path file) : scene(std::move(initial), std::move(file)) {}

    SceneState scene;  // the document and the selection in it
    PlacementState placement;
    TraceState traces;  // the run in progress, the results shown and the event selected in them
    ViewState view;     // camera, layers, slice plane
    UiState ui;         // status line, prompts, screenshots
};

}  // namespace dropscope::gui
