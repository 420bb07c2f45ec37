#pragma once

#include "gui/FrameClient.hpp"
#include "gui/window/WindowSettings.hpp"  // defaultSettingsDirectory
#include "render/GlFunctions.hpp"

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

namespace dropscope::gui {

struct WindowOptions {
    std::string title = "dropscope";
    int width = 1280;  // logical pixels, used when no size is remembered; clamped to 320..16384
    int height = 800;
    std::filesystem::path settingsFile;  // window size remembered here between runs; empty = not remembered
};

// Makes the app once the window's OpenGL context is current. The client owns the ImGui context (the
// window creates none); the function table outlives the client.
using ClientFactory = std::function<std::unique_ptr<FrameClient>(const render::GlFunctions&)>;

// The exit code when no window can be opened.
inline constexpr int kNoWindowExitCode = 3;

// Opens a GLFW window with an OpenGL 3.3 core context (vsync on), makes the client and drives it once per
// frame until the user closes the window or the client asks to quit; returns 0 then. Without a display
// (neither DISPLAY nor WAYLAND_DISPLAY set), or when GLFW cannot open the window, writes one line to
// `err` that points to `dropscope snapshot` and returns kNoWindowExitCode. GLFW errors while the window
// is open go to `err` as "dropscope: GLFW: ...". Exceptions from the factory or the client propagate
// (the window is closed first).
int runWindow(const WindowOptions& options, const ClientFactory& makeClient, std::ostream& err);

}  // namespace dropscope::gui
