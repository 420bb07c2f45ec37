#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

namespace dropscope::gui {

// Key indices of io.KeysDown (ImGui 1.86 leaves the numbering to the platform layer). Printable keys
// are their upper-case ASCII codes ('A'..'Z', '0'..'9', ' '); the others start at 256. The GLFW window
// translates its keys into these; the UI tests press them directly.
enum Key : int {
    kKeySpace = ' ',
    kKeyTab = 256,
    kKeyLeft,
    kKeyRight,
    kKeyUp,
    kKeyDown,
    kKeyPageUp,
    kKeyPageDown,
    kKeyHome,
    kKeyEnd,
    kKeyInsert,
    kKeyDelete,
    kKeyBackspace,
    kKeyEnter,
    kKeyEscape,
    kKeyKeypadEnter,
    kKeyF1,
    kKeyF2,
    kKeyF3,
    kKeyF4,
    kKeyF5,
    kKeyF6,
    kKeyF7,
    kKeyF8,
    kKeyF9,
    kKeyF10,
    kKeyF11,
    kKeyF12,
    kKeyCount = 512
};

// Everything the platform reports for one frame: the state of mouse and keyboard at the frame's start
// and the characters typed since the last one. The GLFW window fills it from its callbacks, the UI
// tests by hand; applyInput (ImGuiInput.hpp) hands it to ImGui the same way for both.
struct InputFrame {
    double deltaSeconds = 1.0 / 60.0;
    int windowWidth = 1280;  // logical pixels (the mouse's coordinates)
    int windowHeight = 800;
    int framebufferWidth = 1280;  // device pixels (what is rendered)
    int framebufferHeight = 800;
    bool mouseInside = false;  // false: the cursor is outside the window
    float mouseX = 0.0f;       // logical pixels from the top-left corner
    float mouseY = 0.0f;
    std::array<bool, 3> mouseDown{};  // left, right, middle
    float wheelX = 0.0f;              // scroll since the last frame, in lines
    float wheelY = 0.0f;
    std::bitset<kKeyCount> keysDown;
    bool ctrl = false;
    bool shift = false;
    bool alt = false;
    bool super = false;
    std::vector<std::uint32_t> characters;  // Unicode code points typed since the last frame
};

}  // namespace dropscope::gui
