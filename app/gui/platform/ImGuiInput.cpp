#include "gui/platform/ImGuiInput.hpp"

#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdint>

namespace dropscope::gui {

namespace {

constexpr const char* kBackendName = "dropscope_input";

// ImGui asserts DeltaTime > 0; two frames in the same clock tick (or a clock going backwards) get this.
constexpr double kMinimumDeltaSeconds = 1e-5;

static_assert(sizeof(ImGuiIO::KeysDown) / sizeof(ImGuiIO::KeysDown[0]) == kKeyCount,
              "our Key indices must cover exactly ImGui 1.86's io.KeysDown");
static_assert(sizeof(ImGuiIO::MouseDown) / sizeof(ImGuiIO::MouseDown[0]) >=
                  std::tuple_size_v<decltype(InputFrame::mouseDown)>,
              "ImGui has a slot for every mouse button the frame reports");

}  // namespace

void configureImGuiIo(ImGuiIO& io) {
    io.BackendPlatformName = kBackendName;
    io.BackendFlags &=
        ~(ImGuiBackendFlags_HasGamepad | ImGuiBackendFlags_HasMouseCursors | ImGuiBackendFlags_HasSetMousePos);

    io.KeyMap[ImGuiKey_Tab] = kKeyTab;
    io.KeyMap[ImGuiKey_LeftArrow] = kKeyLeft;
    io.KeyMap[ImGuiKey_RightArrow] = kKeyRight;
    io.KeyMap[ImGuiKey_UpArrow] = kKeyUp;
    io.KeyMap[ImGuiKey_DownArrow] = kKeyDown;
    io.KeyMap[ImGuiKey_PageUp] = kKeyPageUp;
    io.KeyMap[ImGuiKey_PageDown] = kKeyPageDown;
    io.KeyMap[ImGuiKey_Home] = kKeyHome;
    io.KeyMap[ImGuiKey_End] = kKeyEnd;
    io.KeyMap[ImGuiKey_Insert] = kKeyInsert;
    io.KeyMap[ImGuiKey_Delete] = kKeyDelete;
    io.KeyMap[ImGuiKey_Backspace] = kKeyBackspace;
    io.KeyMap[ImGuiKey_Space] = kKeySpace;
    io.KeyMap[ImGuiKey_Enter] = kKeyEnter;
    io.KeyMap[ImGuiKey_Escape] = kKeyEscape;
    io.KeyMap[ImGuiKey_KeyPadEnter] = kKeyKeypadEnter;
    // Text editing shortcuts (Ctrl+A, C, V, X, Y, Z): letters are their upper-case ASCII codes.
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyMap[ImGuiKey_C] = 'C';
    io.KeyMap[ImGuiKey_V] = 'V';
    io.KeyMap[ImGuiKey_X] = 'X';
    io.KeyMap[ImGuiKey_Y] = 'Y';
    io.KeyMap[ImGuiKey_Z] = 'Z';
}

void applyInput(ImGuiIO& io, const InputFrame& input) {
    io.DisplaySize = ImVec2(static_cast<float>(input.windowWidth), static_cast<float>(input.windowHeight));
    io.DisplayFramebufferScale =
        input.windowWidth > 0 && input.windowHeight > 0
            ? ImVec2(static_cast<float>(input.framebufferWidth) / static_cast<float>(input.windowWidth),
                     static_cast<float>(input.framebufferHeight) / static_cast<float>(input.windowHeight))
            : ImVec2(1.0f, 1.0f);
    // Written so that NaN also takes the minimum.
    io.DeltaTime =
        static_cast<float>(input.deltaSeconds > kMinimumDeltaSeconds ? input.deltaSeconds : kMinimumDeltaSeconds);

    io.MousePos = input.mouseInside ? ImVec2(input.mouseX, input.mouseY) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (std::size_t button = 0; button < input.mouseDown.size(); ++button) {
        io.MouseDown[button] = input.mouseDown[button];
    }
    io.MouseWheel = input.wheelY;
    io.MouseWheelH = input.wheelX;

    for (std::size_t key = 0; key < input.keysDown.size(); ++key) io.KeysDown[key] = input.keysDown[key];
    io.KeyCtrl = input.ctrl;
    io.KeyShift = input.shift;
    io.KeyAlt = input.alt;
    io.KeySuper = input.super;
    for (const std::uint32_t character : input.characters) io.AddInputCharacter(character);
}

}  // namespace dropscope::gui
