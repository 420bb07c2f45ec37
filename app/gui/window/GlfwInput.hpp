#pragma once

#include "gui/platform/InputFrame.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

struct GLFWwindow;

namespace dropscope::gui {

// Our key index (InputFrame.hpp) for a GLFW_KEY_* code: printable keys are their ASCII codes (GLFW's
// codes for them are already upper-case ASCII: letters, digits, space, punctuation), then the named keys
// and F1..F12. Nothing for keys the GUI does not use (keypad digits, modifiers, F13 and up, ...).
std::optional<Key> keyFromGlfw(int glfwKey);

// Collects a GLFW window's input between frames through its callbacks (it takes the window's user
// pointer) and hands it out as one InputFrame per frame.
//
// A key or button pressed and released between two frames (a fast click, xdotool, a key chord typed in
// one go) still shows as down in the next frame and as up in the one after, so ImGui sees every press.
class GlfwInput {
public:
    explicit GlfwInput(GLFWwindow* window);
    ~GlfwInput();
    GlfwInput(const GlfwInput&) = delete;
    GlfwInput& operator=(const GlfwInput&) = delete;

    // The state now and everything typed or scrolled since the last call; call after glfwPollEvents.
    InputFrame nextFrame(double deltaSeconds);

private:
    // Down at some time since the last frame: a key pressed and released between two frames shows for
    // one, and so does a modifier released just before the key of its chord (xdotool's ctrl+q can
    // arrive as ctrl down in one frame, q down, q up, ctrl up before the next).
    struct Latch {
        bool down = false;
        bool downSinceFrame = false;
        bool seen() const { return down || downSinceFrame; }
        void set(bool pressed);
    };
    static constexpr int kGlfwKeyCount = 349;   // GLFW_KEY_LAST + 1, checked in the .cpp
    static constexpr int kGlfwButtonCount = 8;  // GLFW_MOUSE_BUTTON_LAST + 1, checked in the .cpp

    static GlfwInput& of(GLFWwindow* window);
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onScroll(GLFWwindow* window, double x, double y);
    static void onCharacter(GLFWwindow* window, unsigned int codepoint);
    static void onCursorEnter(GLFWwindow* window, int entered);

    GLFWwindow* window_;
    std::array<Latch, kGlfwKeyCount> keys_{};
    std::array<Latch, kGlfwButtonCount> buttons_{};
    bool cursorInside_ = false;
    double wheelX_ = 0.0;
    double wheelY_ = 0.0;
    std::vector<std::uint32_t> characters_;
};

}  // namespace dropscope::gui
