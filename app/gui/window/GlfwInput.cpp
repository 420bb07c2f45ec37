#include "gui/window/GlfwInput.hpp"

#define GLFW_INCLUDE_NONE  // GLFW only; every GL function goes through render::GlFunctions
#include <GLFW/glfw3.h>

#include <utility>

namespace dropscope::gui {

namespace {

struct NamedKey {
    int glfw;
    Key key;
};

constexpr NamedKey kNamedKeys[] = {
    {GLFW_KEY_TAB, kKeyTab},
    {GLFW_KEY_LEFT, kKeyLeft},
    {GLFW_KEY_RIGHT, kKeyRight},
    {GLFW_KEY_UP, kKeyUp},
    {GLFW_KEY_DOWN, kKeyDown},
    {GLFW_KEY_PAGE_UP, kKeyPageUp},
    {GLFW_KEY_PAGE_DOWN, kKeyPageDown},
    {GLFW_KEY_HOME, kKeyHome},
    {GLFW_KEY_END, kKeyEnd},
    {GLFW_KEY_INSERT, kKeyInsert},
    {GLFW_KEY_DELETE, kKeyDelete},
    {GLFW_KEY_BACKSPACE, kKeyBackspace},
    {GLFW_KEY_ENTER, kKeyEnter},
    {GLFW_KEY_ESCAPE, kKeyEscape},
    {GLFW_KEY_KP_ENTER, kKeyKeypadEnter},
};

bool isPrintable(int glfwKey) {
    return glfwKey == GLFW_KEY_SPACE || glfwKey == GLFW_KEY_APOSTROPHE ||
           (glfwKey >= GLFW_KEY_COMMA && glfwKey <= GLFW_KEY_9) || glfwKey == GLFW_KEY_SEMICOLON ||
           glfwKey == GLFW_KEY_EQUAL || (glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_RIGHT_BRACKET) ||
           glfwKey == GLFW_KEY_GRAVE_ACCENT;
}

}  // namespace

std::optional<Key> keyFromGlfw(int glfwKey) {
    if (isPrintable(glfwKey)) return static_cast<Key>(glfwKey);
    if (glfwKey >= GLFW_KEY_F1 && glfwKey <= GLFW_KEY_F12) return static_cast<Key>(kKeyF1 + (glfwKey - GLFW_KEY_F1));
    for (const NamedKey& named : kNamedKeys) {
        if (named.glfw == glfwKey) return named.key;
    }
    return std::nullopt;
}

void GlfwInput::Latch::set(bool pressed) {
    down = pressed;
    if (pressed) downSinceFrame = true;
}

GlfwInput::GlfwInput(GLFWwindow* window) : window_(window) {
    static_assert(kGlfwKeyCount == GLFW_KEY_LAST + 1);
    static_assert(kGlfwButtonCount == GLFW_MOUSE_BUTTON_LAST + 1);
    static_assert(GLFW_MOUSE_BUTTON_LEFT == 0 && GLFW_MOUSE_BUTTON_RIGHT == 1 && GLFW_MOUSE_BUTTON_MIDDLE == 2,
                  "InputFrame::mouseDown is left, right, middle: GLFW's first three buttons");
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, onKey);
    glfwSetMouseButtonCallback(window_, onMouseButton);
    glfwSetScrollCallback(window_, onScroll);
    glfwSetCharCallback(window_, onCharacter);
    glfwSetCursorEnterCallback(window_, onCursorEnter);
    cursorInside_ = glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE;
}

GlfwInput::~GlfwInput() {
    glfwSetKeyCallback(window_, nullptr);
    glfwSetMouseButtonCallback(window_, nullptr);
    glfwSetScrollCallback(window_, nullptr);
    glfwSetCharCallback(window_, nullptr);
    glfwSetCursorEnterCallback(window_, nullptr);
    glfwSetWindowUserPointer(window_, nullptr);
}

GlfwInput& GlfwInput::of(GLFWwindow* window) { return *static_cast<GlfwInput*>(glfwGetWindowUserPointer(window)); }

void GlfwInput::onKey(GLFWwindow* window, int key, int, int action, int) {
    if (key < 0 || key >= kGlfwKeyCount || action == GLFW_REPEAT) return;  // a repeat changes nothing
    of(window).keys_[static_cast<std::size_t>(key)].set(action == GLFW_PRESS);
}

void GlfwInput::onMouseButton(GLFWwindow* window, int button, int action, int) {
    if (button < 0 || button >= kGlfwButtonCount) return;
    of(window).buttons_[static_cast<std::size_t>(button)].set(action == GLFW_PRESS);
}

void GlfwInput::onScroll(GLFWwindow* window, double x, double y) {
    GlfwInput& input = of(window);
    input.wheelX_ += x;
    input.wheelY_ += y;
}

void GlfwInput::onCharacter(GLFWwindow* window, unsigned int codepoint) { of(window).characters_.push_back(codepoint); }

void GlfwInput::onCursorEnter(GLFWwindow* window, int entered) { of(window).cursorInside_ = entered == GLFW_TRUE; }

InputFrame GlfwInput::nextFrame(double deltaSeconds) {
    InputFrame frame;
    frame.deltaSeconds = deltaSeconds;
    glfwGetWindowSize(window_, &frame.windowWidth, &frame.windowHeight);
    glfwGetFramebufferSize(window_, &frame.framebufferWidth, &frame.framebufferHeight);

    bool anyButton = false;
    for (std::size_t button = 0; button < frame.mouseDown.size(); ++button) {
        frame.mouseDown[button] = buttons_[button].seen();
        anyButton = anyButton || frame.mouseDown[button];
    }
    // A drag that leaves the window keeps reporting its position (X11 holds the pointer for the window
    // while a button is down), so a slider or a panel being moved follows the mouse past the edge.
    frame.mouseInside = cursorInside_ || anyButton;
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    frame.mouseX = static_cast<float>(x);
    frame.mouseY = static_cast<float>(y);
    frame.wheelX = static_cast<float>(std::exchange(wheelX_, 0.0));
    frame.wheelY = static_cast<float>(std::exchange(wheelY_, 0.0));

    for (int glfwKey = 0; glfwKey < kGlfwKeyCount; ++glfwKey) {
        if (!keys_[static_cast<std::size_t>(glfwKey)].seen()) continue;
        if (const std::optional<Key> key = keyFromGlfw(glfwKey)) frame.keysDown.set(static_cast<std::size_t>(*key));
    }
    const auto seen = [&](int left, int right) {
        return keys_[static_cast<std::size_t>(left)].seen() || keys_[static_cast<std::size_t>(right)].seen();
    };
    frame.ctrl = seen(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    frame.shift = seen(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    frame.alt = seen(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    frame.super = seen(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
    frame.characters = std::exchange(characters_, {});

    for (Latch& key : keys_) key.downSinceFrame = key.down;
    for (Latch& button : buttons_) button.downSinceFrame = button.down;
    return frame;
}

}  // namespace dropscope::gui
