// applyInput hands an InputFrame to ImGui: clicks, keys and typed text reach widgets as a user's would,
// and the display, time step, wheel and modifiers arrive as given. No GL: ImGui frames without drawing.
#include "gui/platform/ImGuiInput.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cfloat>
#include <cstring>
#include <functional>
#include <string>
#include <utility>

namespace dropscope::gui {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

struct ImGuiContextOwner {
    ImGuiContext* context = ImGui::CreateContext();
    ~ImGuiContextOwner() { ImGui::DestroyContext(context); }
};

class ImGuiInputTest : public ::testing::Test {
protected:
    ImGuiInputTest() {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        configureImGuiIo(io);
        io.Fonts->Build();  // NewFrame needs the atlas built; nothing is drawn here
    }

    // A frame with the mouse outside the window, no buttons and no keys.
    static InputFrame idle() {
        InputFrame input;
        input.windowWidth = input.framebufferWidth = kWidth;
        input.windowHeight = input.framebufferHeight = kHeight;
        return input;
    }
    static InputFrame mouseAt(ImVec2 position, bool leftDown) {
        InputFrame input = idle();
        input.mouseInside = true;
        input.mouseX = position.x;
        input.mouseY = position.y;
        input.mouseDown[0] = leftDown;
        return input;
    }

    // One ImGui frame of `ui` with `input`.
    static void frame(const InputFrame& input, const std::function<void()>& ui) {
        applyInput(ImGui::GetIO(), input);
        ImGui::NewFrame();
        ui();
        ImGui::Render();
    }

    // A fixed panel at (10, 10) holding `content`.
    static void panel(const std::function<void()>& content) {
        ImGui::SetNextWindowPos({10, 10});
        ImGui::SetNextWindowSize({240, 160});
        ImGui::Begin("input", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
        content();
        ImGui::End();
    }

    ImGuiContextOwner imgui_;
};

TEST_F(ImGuiInputTest, APressAndReleaseOverAButtonClicksItOnce) {
    int clicks = 0;
    ImVec2 center;
    const auto ui = [&] {
        panel([&] {
            if (ImGui::Button("Fire", {100, 40})) ++clicks;
            const ImVec2 min = ImGui::GetItemRectMin();
            const ImVec2 max = ImGui::GetItemRectMax();
            center = {(min.x + max.x) / 2, (min.y + max.y) / 2};
        });
    };
    frame(idle(), ui);
    frame(idle(), ui);
    ASSERT_GT(center.x, 10.0f);

    frame(mouseAt(center, false), ui);  // hover
    frame(mouseAt(center, true), ui);   // press
    EXPECT_EQ(clicks, 0) << "a button fires on release";
    frame(mouseAt(center, false), ui);  // release
    EXPECT_EQ(clicks, 1);
    frame(mouseAt(center, false), ui);
    frame(idle(), ui);
    EXPECT_EQ(clicks, 1) << "exactly once";
}

TEST_F(ImGuiInputTest, AKeyIsPressedOnTheFrameItGoesDownAndReleasedWhenItComesUp) {
    InputFrame down = idle();
    down.keysDown.set(kKeyF12);
    bool pressed = false;
    bool released = false;
    const auto watch = [&] {
        pressed = ImGui::IsKeyPressed(kKeyF12, false);
        released = ImGui::IsKeyReleased(kKeyF12);
    };
    frame(idle(), watch);
    EXPECT_FALSE(pressed);
    frame(down, watch);
    EXPECT_TRUE(pressed) << "the frame it goes down";
    EXPECT_TRUE(ImGui::IsKeyDown(kKeyF12));
    frame(down, watch);
    EXPECT_FALSE(pressed) << "held, not pressed again";
    frame(idle(), watch);
    EXPECT_FALSE(pressed);
    EXPECT_TRUE(released);
}

TEST_F(ImGuiInputTest, TypedCharactersAndMappedKeysReachAFocusedInputText) {
    char text[64] = "";
    bool focus = true;
    const auto ui = [&] {
        panel([&] {
            if (std::exchange(focus, false)) ImGui::SetKeyboardFocusHere();
            ImGui::InputText("##text", text, sizeof text);
        });
    };
    frame(idle(), ui);  // asks for focus
    frame(idle(), ui);  // the field takes it
    InputFrame typing = idle();
    typing.characters = {'d', 'r', 'o', 'p'};
    frame(typing, ui);
    typing.characters = {'s', 'c', 'o', 'p', 'e', 0x00e9};  // and a non-ASCII code point, é
    frame(typing, ui);
    frame(idle(), ui);
    EXPECT_STREQ(text, "dropscope\xc3\xa9");

    InputFrame backspace = idle();
    backspace.keysDown.set(kKeyBackspace);  // through io.KeyMap[ImGuiKey_Backspace]
    frame(backspace, ui);
    frame(idle(), ui);
    EXPECT_STREQ(text, "dropscope");
}

TEST_F(ImGuiInputTest, TheMouseOutsideTheWindowHasNoPosition) {
    InputFrame outside = mouseAt({5, 6}, false);
    outside.mouseInside = false;
    frame(outside, [] {});
    EXPECT_EQ(ImGui::GetIO().MousePos.x, -FLT_MAX);
    EXPECT_EQ(ImGui::GetIO().MousePos.y, -FLT_MAX);
    EXPECT_FALSE(ImGui::IsMousePosValid());

    frame(mouseAt({5, 6}, false), [] {});
    EXPECT_TRUE(ImGui::IsMousePosValid());
    EXPECT_EQ(ImGui::GetIO().MousePos.x, 5.0f);
    EXPECT_EQ(ImGui::GetIO().MousePos.y, 6.0f);
}

TEST_F(ImGuiInputTest, DisplayTimeWheelAndModifiersArriveAsGiven) {
    InputFrame input = idle();
    input.windowWidth = 640;
    input.windowHeight = 400;
    input.framebufferWidth = 1280;
    input.framebufferHeight = 800;
    input.deltaSeconds = 0.0;  // two frames in one clock tick
    input.wheelX = -1.0f;
    input.wheelY = 2.5f;
    input.ctrl = true;
    input.super = true;
    applyInput(ImGui::GetIO(), input);

    const ImGuiIO& io = ImGui::GetIO();
    EXPECT_EQ(io.DisplaySize.x, 640.0f);
    EXPECT_EQ(io.DisplaySize.y, 400.0f);
    EXPECT_EQ(io.DisplayFramebufferScale.x, 2.0f);
    EXPECT_EQ(io.DisplayFramebufferScale.y, 2.0f);
    EXPECT_GT(io.DeltaTime, 0.0f) << "ImGui asserts a positive time step";
    EXPECT_EQ(io.MouseWheel, 2.5f);
    EXPECT_EQ(io.MouseWheelH, -1.0f);
    EXPECT_TRUE(io.KeyCtrl);
    EXPECT_FALSE(io.KeyShift);
    EXPECT_FALSE(io.KeyAlt);
    EXPECT_TRUE(io.KeySuper);
    frame(input, [] {});  // and ImGui takes it
}

TEST_F(ImGuiInputTest, ImGuisKeysMapToOurKeyIndices) {
    const ImGuiIO& io = ImGui::GetIO();
    EXPECT_EQ(io.KeyMap[ImGuiKey_Tab], kKeyTab);
    EXPECT_EQ(io.KeyMap[ImGuiKey_Space], kKeySpace);
    EXPECT_EQ(io.KeyMap[ImGuiKey_Escape], kKeyEscape);
    EXPECT_EQ(io.KeyMap[ImGuiKey_KeyPadEnter], kKeyKeypadEnter);
    EXPECT_EQ(io.KeyMap[ImGuiKey_A], 'A');
    EXPECT_EQ(io.KeyMap[ImGuiKey_Z], 'Z');
    for (int key = 0; key < ImGuiKey_COUNT; ++key) {
        EXPECT_GE(io.KeyMap[key], 0) << "ImGuiKey " << key << " is mapped";
        EXPECT_LT(io.KeyMap[key], kKeyCount);
    }
    ASSERT_NE(io.BackendPlatformName, nullptr);
}

}  // namespace
}  // namespace dropscope::gui
