#pragma once

#include "gui/PanelState.hpp"
#include "gui/StatusLine.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace dropscope::gui {

// The screenshot the next frame writes, after everything is drawn.
struct ScreenshotRequest {
    std::filesystem::path file;
    bool panels = false;
    int width = 0;  // 0: the window's size (panels or not)
    int height = 0;
    int delayFrames = 0;  // frames to wait first, e.g. until the dialog that asked for it has closed
};

// Where a widget was drawn, in ImGui's display coordinates (window pixels).
struct ItemRect {
    float minX = 0.0f;
    float minY = 0.0f;
    float maxX = 0.0f;
    float maxY = 0.0f;
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
    // A few fields' places as last drawn (the shape editor's "centre"), by name: where the UI tests click
    // to type into them, as a user would, without depending on the panel's layout.
    std::map<std::string, ItemRect> itemRects;
    PanelState panels;  // started afresh when a scene is opened
};

}  // namespace dropscope::gui
