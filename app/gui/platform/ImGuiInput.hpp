#pragma once

#include "gui/platform/InputFrame.hpp"

#include <imgui.h>

namespace dropscope::gui {

// Once per ImGui context: io.KeyMap from ImGui's keys to our Key indices (InputFrame.hpp), the platform
// backend's name, and its flags (none: the window neither changes the cursor's shape nor moves it).
void configureImGuiIo(ImGuiIO& io);

// Before each ImGui::NewFrame: the frame's display size and framebuffer scale, time step, mouse,
// keys, modifiers and typed characters, the same way for the GLFW window and for the UI tests.
void applyInput(ImGuiIO& io, const InputFrame& input);

}  // namespace dropscope::gui
