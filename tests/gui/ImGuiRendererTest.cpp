// ImGuiRenderer draws ImGui's output through the GlFunctions table: panels land where ImGui put them, in
// their colours, with text; clip rectangles become scissor boxes; large lists use VtxOffset; user
// callbacks run; and the GL state it changes is put back. All headless, in an OSMesa buffer.
#include "gui/platform/ImGuiInput.hpp"
#include "gui/platform/ImGuiRenderer.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <optional>

namespace dropscope::gui {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
// Frames drawn before looking at pixels: a new ImGui window is hidden on its first frame (auto-fit).
constexpr int kSettleFrames = 2;
// Per colour channel, in 8-bit steps: the float-to-byte rounding of a colour, and the font atlas's white
// pixel sampled with linear filtering, may each move a channel by one step.
constexpr int kColourTolerance = 2;
// Pixels kept away from a panel's edge when checking its inside: its 1-pixel border, anti-aliased.
constexpr int kEdgeMargin = 3;

using Rgb = std::array<int, 3>;
// Colours exactly representable in 8 bits, far apart from one another.
constexpr Rgb kClear{32, 64, 96};
constexpr Rgb kPanel{200, 120, 40};
constexpr Rgb kMagenta{255, 0, 255};
constexpr Rgb kGreen{0, 255, 0};

ImVec4 toImVec4(const Rgb& colour) {
    return {static_cast<float>(colour[0]) / 255.0f, static_cast<float>(colour[1]) / 255.0f,
            static_cast<float>(colour[2]) / 255.0f, 1.0f};
}
ImU32 toImU32(const Rgb& colour) { return ImGui::ColorConvertFloat4ToU32(toImVec4(colour)); }

bool near(const snapshot::Image& image, int x, int y, const Rgb& colour) {
    const std::uint8_t* pixel = image.pixel(x, y);
    for (int c = 0; c < 3; ++c) {
        if (std::abs(static_cast<int>(pixel[c]) - colour[c]) > kColourTolerance) return false;
    }
    return true;
}

struct Rect {
    int minX, minY, maxX, maxY;  // pixels [min, max)
};

Rect toRect(const ImVec2& min, const ImVec2& max) {
    return {static_cast<int>(min.x), static_cast<int>(min.y), static_cast<int>(max.x), static_cast<int>(max.y)};
}

// Whether every pixel of `area` (clipped to the image) satisfies `test`; reports the first that does not.
template <class Test>
::testing::AssertionResult everyPixel(const snapshot::Image& image, const Rect& area, Test test) {
    for (int y = std::max(area.minY, 0); y < std::min(area.maxY, image.height); ++y) {
        for (int x = std::max(area.minX, 0); x < std::min(area.maxX, image.width); ++x) {
            if (!test(x, y)) return ::testing::AssertionFailure() << "at pixel (" << x << ", " << y << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

// A frame with no mouse and no keys, window and framebuffer both width x height.
InputFrame displayOfSize(int width, int height) {
    InputFrame input;
    input.windowWidth = input.framebufferWidth = width;
    input.windowHeight = input.framebufferHeight = height;
    return input;
}

// Owns an ImGui context for one test (the renderer needs it current from construction to destruction).
struct ImGuiContextOwner {
    ImGuiContext* context = ImGui::CreateContext();
    ~ImGuiContextOwner() { ImGui::DestroyContext(context); }
};

class ImGuiRendererTest : public ::testing::Test {
protected:
    ImGuiRendererTest() {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        configureImGuiIo(io);
        renderer_.emplace(osmesa_.gl());
    }
    ~ImGuiRendererTest() override { renderer_.reset(); }

    // Runs `frames` ImGui frames of `ui` at `input`'s size, each drawn over the clear colour; the last one.
    snapshot::Image draw(const std::function<void()>& ui, int frames = kSettleFrames) {
        const render::GlFunctions& gl = osmesa_.gl();
        for (int frame = 0; frame < frames; ++frame) {
            applyInput(ImGui::GetIO(), input_);
            ImGui::NewFrame();
            ui();
            ImGui::Render();
            gl.Viewport(0, 0, kWidth, kHeight);
            gl.ClearColor(static_cast<float>(kClear[0]) / 255.0f, static_cast<float>(kClear[1]) / 255.0f,
                          static_cast<float>(kClear[2]) / 255.0f, 1.0f);
            gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            renderer_->render(ImGui::GetDrawData());
        }
        EXPECT_EQ(gl.GetError(), static_cast<GLenum>(GL_NO_ERROR));
        return osmesa_.read();
    }

    // A fixed panel (no title bar, no resizing) in kPanel; `content` fills it.
    static void panel(const char* name, ImVec2 position, ImVec2 size, const std::function<void()>& content) {
        ImGui::SetNextWindowPos(position);
        ImGui::SetNextWindowSize(size);
        ImGui::PushStyleColor(ImGuiCol_WindowBg, toImVec4(kPanel));
        ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
        content();
        ImGui::End();
        ImGui::PopStyleColor();
    }

    snapshot::OsmesaContext osmesa_{kWidth, kHeight};
    ImGuiContextOwner imgui_;
    std::optional<ImGuiRenderer> renderer_;
    InputFrame input_ = displayOfSize(kWidth, kHeight);
};

TEST_F(ImGuiRendererTest, PanelHasItsBackgroundAndTextOverTheClearColour) {
    const Rect window{40, 30, 240, 180};
    ImVec2 textMin;
    ImVec2 textMax;
    const snapshot::Image image = draw([&] {
        panel("panel", {40, 30}, {200, 150}, [&] {
            ImGui::TextUnformatted("dropscope 0123 WWW");
            textMin = ImGui::GetItemRectMin();
            textMax = ImGui::GetItemRectMax();
        });
    });
    const Rect text = toRect(textMin, textMax);
    ASSERT_GT(text.maxX - text.minX, 50);
    ASSERT_GE(text.minY, window.minY);

    const auto isClear = [&](int x, int y) { return near(image, x, y, kClear); };
    const auto isPanel = [&](int x, int y) { return near(image, x, y, kPanel); };
    EXPECT_TRUE(everyPixel(image, {0, 0, kWidth, window.minY - 1}, isClear)) << "above the panel";
    EXPECT_TRUE(everyPixel(image, {0, window.maxY + 1, kWidth, kHeight}, isClear)) << "below the panel";
    EXPECT_TRUE(everyPixel(image, {0, 0, window.minX - 1, kHeight}, isClear)) << "left of the panel";
    EXPECT_TRUE(everyPixel(image, {window.maxX + 1, 0, kWidth, kHeight}, isClear)) << "right of the panel";
    EXPECT_TRUE(everyPixel(
        image,
        {window.minX + kEdgeMargin, text.maxY + kEdgeMargin, window.maxX - kEdgeMargin, window.maxY - kEdgeMargin},
        isPanel))
        << "inside the panel, below the text";

    int textPixels = 0;
    for (int y = text.minY; y < text.maxY; ++y) {
        for (int x = text.minX; x < text.maxX; ++x) textPixels += isPanel(x, y) ? 0 : 1;
    }
    EXPECT_GT(textPixels, 50) << "glyphs drawn inside the panel";
}

TEST_F(ImGuiRendererTest, ScissorKeepsAChildRegionsContentInsideItsClipRectangle) {
    constexpr float kOverhang = 30.0f;  // how far the filled rectangle reaches past the child's clip
    ImVec2 clipMin;
    ImVec2 clipMax;
    const snapshot::Image image = draw([&] {
        panel("panel", {20, 20}, {280, 200}, [&] {
            ImGui::SetCursorPos({60, 60});
            ImGui::BeginChild("clipped", {120, 60});
            ImDrawList* list = ImGui::GetWindowDrawList();
            clipMin = list->GetClipRectMin();
            clipMax = list->GetClipRectMax();
            list->AddRectFilled({clipMin.x - kOverhang, clipMin.y - kOverhang},
                                {clipMax.x + kOverhang, clipMax.y + kOverhang}, toImU32(kMagenta));
            ImGui::EndChild();
        });
    });
    const Rect clip = toRect(clipMin, clipMax);
    ASSERT_GT(clip.maxX - clip.minX, 100);
    ASSERT_GT(clip.maxY - clip.minY, 40);

    EXPECT_TRUE(everyPixel(image, clip, [&](int x, int y) { return near(image, x, y, kMagenta); }))
        << "inside the clip rectangle";
    const int reach = static_cast<int>(kOverhang) + 2;
    const Rect around{clip.minX - reach, clip.minY - reach, clip.maxX + reach, clip.maxY + reach};
    EXPECT_TRUE(everyPixel(image, around, [&](int x, int y) {
        const bool inside = x >= clip.minX && x < clip.maxX && y >= clip.minY && y < clip.maxY;
        return inside || near(image, x, y, kPanel);
    })) << "outside the clip rectangle, where the rectangle reaches without a scissor";
}

TEST_F(ImGuiRendererTest, DrawsAListLargerThan16BitIndicesThroughVertexOffsets) {
    constexpr int kRectangles = 20000;  // 4 vertices each: 80000 vertices, past 65536
    const snapshot::Image image = draw([&] {
        panel("panel", {20, 20}, {280, 200}, [&] {
            ImDrawList* list = ImGui::GetWindowDrawList();
            for (int i = 0; i < kRectangles; ++i) list->AddRectFilled({30, 30}, {40, 40}, toImU32(kMagenta));
            list->AddRectFilled({200, 150}, {240, 190}, toImU32(kGreen));
        });
    });
    bool offset = false;
    const ImDrawData* data = ImGui::GetDrawData();
    for (int n = 0; n < data->CmdListsCount; ++n) {
        for (const ImDrawCmd& command : data->CmdLists[n]->CmdBuffer) offset = offset || command.VtxOffset > 0;
    }
    EXPECT_TRUE(offset) << "ImGui split the list with a VtxOffset";
    EXPECT_TRUE(everyPixel(image, {32, 32, 38, 38}, [&](int x, int y) { return near(image, x, y, kMagenta); }));
    EXPECT_TRUE(everyPixel(image, {201, 151, 239, 189}, [&](int x, int y) { return near(image, x, y, kGreen); }))
        << "the rectangle drawn after the split";
}

// What a user callback sees and does: counts its calls, then leaves GL in a state ImGui cannot draw in.
struct CallbackRecord {
    const render::GlFunctions* gl = nullptr;
    int calls = 0;
};

void spoilState(const ImDrawList*, const ImDrawCmd* command) {
    auto& record = *static_cast<CallbackRecord*>(command->UserCallbackData);
    ++record.calls;
    record.gl->UseProgram(0);
    record.gl->BindVertexArray(0);
    record.gl->Disable(GL_BLEND);
}

TEST_F(ImGuiRendererTest, RunsUserCallbacksAndResetsItsStateOnRequest) {
    CallbackRecord record{&osmesa_.gl()};
    const snapshot::Image image = draw([&] {
        panel("panel", {20, 20}, {280, 200}, [&] {
            ImDrawList* list = ImGui::GetWindowDrawList();
            list->AddCallback(spoilState, &record);
            list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
            list->AddRectFilled({100, 100}, {140, 140}, toImU32(kGreen));
        });
    });
    EXPECT_EQ(record.calls, kSettleFrames) << "once per frame drawn";
    EXPECT_TRUE(everyPixel(image, {101, 101, 139, 139}, [&](int x, int y) { return near(image, x, y, kGreen); }))
        << "drawn after the reset";
}

TEST_F(ImGuiRendererTest, DrawsInFramebufferPixelsWhenTheFramebufferIsScaled) {
    input_.windowWidth = kWidth / 2;  // a high-density display: two device pixels per logical pixel
    input_.windowHeight = kHeight / 2;
    ImVec2 clipMin;
    ImVec2 clipMax;
    const snapshot::Image image = draw([&] {
        panel("panel", {20, 15}, {100, 75}, [&] {
            ImGui::SetCursorPos({20, 20});
            ImGui::BeginChild("clipped", {40, 20});
            ImDrawList* list = ImGui::GetWindowDrawList();
            clipMin = list->GetClipRectMin();
            clipMax = list->GetClipRectMax();
            list->AddRectFilled({0, 0}, {160, 120}, toImU32(kMagenta));
            ImGui::EndChild();
        });
    });
    const Rect window{40, 30, 240, 180};  // the panel, in framebuffer pixels
    const Rect clip = toRect({2 * clipMin.x, 2 * clipMin.y}, {2 * clipMax.x, 2 * clipMax.y});
    const auto isClear = [&](int x, int y) { return near(image, x, y, kClear); };
    EXPECT_TRUE(everyPixel(image, {0, 0, kWidth, window.minY - 1}, isClear)) << "above the panel";
    EXPECT_TRUE(everyPixel(image, {0, 0, window.minX - 1, kHeight}, isClear)) << "left of the panel";
    EXPECT_TRUE(everyPixel(image, {window.maxX + 1, 0, kWidth, kHeight}, isClear)) << "right of the panel";
    EXPECT_TRUE(everyPixel(image, {0, window.maxY + 1, kWidth, kHeight}, isClear)) << "below the panel";
    EXPECT_TRUE(everyPixel(image, clip, [&](int x, int y) { return near(image, x, y, kMagenta); }))
        << "the child's clip rectangle, doubled";
    EXPECT_TRUE(near(image, clip.minX - 2, clip.minY - 2, kPanel));
    EXPECT_TRUE(near(image, clip.maxX + 1, clip.maxY + 1, kPanel));
}

// The state render() changes, read back from GL.
struct ObservedState {
    std::array<GLboolean, 4> enabled{};  // blend, scissor test, depth test, face culling
    std::array<GLint, 4> blendFunctions{};
    std::array<GLint, 4> viewport{};
    std::array<GLint, 4> scissorBox{};
    GLint program = 0;
    GLint vertexArray = 0;
    GLint arrayBuffer = 0;
    GLint activeTexture = 0;
    GLint texture0 = 0;

    static ObservedState read(const render::GlFunctions& gl) {
        ObservedState state;
        const std::array<GLenum, 4> capabilities{GL_BLEND, GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_CULL_FACE};
        for (std::size_t i = 0; i < capabilities.size(); ++i) state.enabled[i] = gl.IsEnabled(capabilities[i]);
        gl.GetIntegerv(GL_BLEND_SRC_RGB, &state.blendFunctions[0]);
        gl.GetIntegerv(GL_BLEND_DST_RGB, &state.blendFunctions[1]);
        gl.GetIntegerv(GL_BLEND_SRC_ALPHA, &state.blendFunctions[2]);
        gl.GetIntegerv(GL_BLEND_DST_ALPHA, &state.blendFunctions[3]);
        gl.GetIntegerv(GL_VIEWPORT, state.viewport.data());
        gl.GetIntegerv(GL_SCISSOR_BOX, state.scissorBox.data());
        gl.GetIntegerv(GL_CURRENT_PROGRAM, &state.program);
        gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &state.vertexArray);
        gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &state.arrayBuffer);
        gl.GetIntegerv(GL_ACTIVE_TEXTURE, &state.activeTexture);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &state.texture0);
        gl.ActiveTexture(static_cast<GLenum>(state.activeTexture));
        return state;
    }
    bool operator==(const ObservedState&) const = default;
};

TEST_F(ImGuiRendererTest, LeavesTheGlStateItChangesAsItFoundIt) {
    const render::GlFunctions& gl = osmesa_.gl();
    // A state unlike ImGui's: what the scene renderer leaves, and then some.
    GLuint vertexArray = 0;
    GLuint buffer = 0;
    GLuint texture = 0;
    gl.GenVertexArrays(1, &vertexArray);
    gl.GenBuffers(1, &buffer);
    gl.GenTextures(1, &texture);
    applyInput(ImGui::GetIO(), input_);
    ImGui::NewFrame();
    panel("panel", {20, 20}, {100, 100}, [] { ImGui::TextUnformatted("state"); });
    ImGui::Render();

    gl.Enable(GL_DEPTH_TEST);
    gl.Enable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_SCISSOR_TEST);
    gl.BlendFuncSeparate(GL_ONE, GL_ZERO, GL_DST_COLOR, GL_ZERO);
    gl.Viewport(3, 4, 100, 50);
    gl.Scissor(5, 6, 7, 8);
    gl.UseProgram(0);
    gl.BindVertexArray(vertexArray);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffer);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, texture);
    gl.ActiveTexture(GL_TEXTURE3);
    const ObservedState before = ObservedState::read(gl);

    renderer_->render(ImGui::GetDrawData());
    EXPECT_EQ(gl.GetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_TRUE(ObservedState::read(gl) == before);

    gl.DeleteTextures(1, &texture);
    gl.DeleteBuffers(1, &buffer);
    gl.DeleteVertexArrays(1, &vertexArray);
}

TEST_F(ImGuiRendererTest, PublishesItsFontTextureAndBackendToImGui) {
    const ImGuiIO& io = ImGui::GetIO();
    EXPECT_EQ(io.Fonts->TexID, renderer_->fontTexture());
    EXPECT_NE(io.Fonts->TexID, nullptr);
    EXPECT_NE(io.BackendFlags & ImGuiBackendFlags_RendererHasVtxOffset, 0);
    ASSERT_NE(io.BackendRendererName, nullptr);
    renderer_.reset();
    EXPECT_EQ(io.Fonts->TexID, nullptr) << "no dangling texture id once the renderer is gone";
    EXPECT_EQ(io.BackendRendererName, nullptr);
}

}  // namespace
}  // namespace dropscope::gui
