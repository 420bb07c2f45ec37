#pragma once

#include "gui/ItemProbe.hpp"
#include "gui/PanelState.hpp"
#include "gui/StatusLine.hpp"

#include <filesystem>
#include <optional>

namespace dropscope::gui {

// The screenshot the next frame writes, after everything is drawn.
struct ScreenshotRequest {
    std::filesystem::path file;
    bool panels = false;
    int width = 0;  // 0: the window's size (panels or not)
    int height = 0;
    int delayFrames = 0;  // frames to wait first, e.g. until the dialog that asked for it has closed
};

// The window around the scene: the status line, the Help window, the file prompt, screenshots, quitting,
// and what the panels keep between frames.
struct UiState {
    StatusLine status;
    bool showHelp = false;
    FilePrompt prompt = FilePrompt::None;
    bool quit = false;
    std::optional<ScreenshotRequest> screenshot;
    std::filesystem::path screenshotDirectory = ".";  // F12's timestamped PNGs
    std::filesystem::path lastScreenshot;
    ItemProbe itemProbe;  // AppOptions::itemProbe
    PanelState panels;    // started afresh when a scene is opened
    // Whether a frame whose 3D view is drawn on the processor gets its panels drawn there too, into the same
    // picture, when they show only text and shapes (gui/platform/ImGuiRasteriser); else OpenGL draws them.
    bool panelsOnProcessor = true;
    // Whether those panels' lists that stay from frame to frame are drawn once into a kept layer and blended from it
    // (gui/platform/KeptPanels); else every list is drawn every frame.
    bool keepPanels = true;
};

}  // namespace dropscope::gui
