#pragma once

#include <filesystem>
#include <optional>

namespace dropscope::gui {

// The window's size in logical pixels, remembered between runs.
struct WindowSize {
    int width = 1280;
    int height = 800;
};

// Bounds on a remembered or requested size: small enough to still show a panel, large enough for any
// screen; a size outside them is brought inside rather than refused.
inline constexpr int kMinimumWindowSide = 320;
inline constexpr int kMaximumWindowSide = 16384;

WindowSize clampWindowSize(WindowSize size);

// Where the GUI keeps its settings: $XDG_CONFIG_HOME/dropscope (when set to an absolute path, as the XDG
// base-directory specification asks) or else $HOME/.config/dropscope; empty when neither is set.
std::filesystem::path defaultSettingsDirectory();

// "width height" from `file`, clamped; nothing for a missing, unreadable or garbled file.
std::optional<WindowSize> readWindowSize(const std::filesystem::path& file);

// Writes "width height" to `file`, creating its folder, through a temporary file renamed over it, so the
// file is never partly written. Throws std::runtime_error or std::filesystem::filesystem_error on failure.
void writeWindowSize(const std::filesystem::path& file, WindowSize size);

}  // namespace dropscope::gui
