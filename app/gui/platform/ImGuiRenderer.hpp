#pragma once

#include "render/GlFunctions.hpp"
#include "render/ShaderProgram.hpp"

#include <imgui.h>

namespace dropscope::gui {

// Draws Dear ImGui's output (ImDrawData) with OpenGL 3.3 core through the same GlFunctions table as the
// scene renderer, into whatever framebuffer is bound: the GLFW window's, an offscreen one, or OSMesa's.
//
// GL state: render() sets what it needs (alpha blending, scissor test, no depth test, no culling, its
// program, texture unit 0, its vertex array, the viewport over the whole framebuffer) and puts every one
// of those back as it found it before returning. It does not touch the depth mask, the clear colour, the
// bound framebuffer or the pixel-store settings, and assumes filled polygons and no sampler object on
// texture unit 0 (the scene renderer uses neither polygon modes nor samplers).
//
// Needs a current ImGui context (ImGui::GetIO()) when constructed and destroyed, and the GL context
// current whenever it is used.
class ImGuiRenderer {
public:
    // Compiles shaders/imgui.vert|frag, builds the font atlas texture from ImGui::GetIO().Fonts (RGBA32)
    // and stores its id in Fonts->TexID; sets io.BackendRendererName and RendererHasVtxOffset.
    // Throws render::RenderError when the shaders do not compile.
    explicit ImGuiRenderer(const render::GlFunctions& gl);
    ~ImGuiRenderer();
    ImGuiRenderer(const ImGuiRenderer&) = delete;
    ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

    // Draws one frame's ImGui::GetDrawData(). Nothing is drawn for a null or empty display.
    void render(const ImDrawData* data);

    // The font atlas as an ImTextureID (what ImGui::Image would take).
    ImTextureID fontTexture() const;

private:
    void setUpState(const ImDrawData& data, int framebufferWidth, int framebufferHeight);
    void upload(const ImDrawData& data);
    void drawCommands(const ImDrawData& data, int framebufferWidth, int framebufferHeight);

    const render::GlFunctions& gl_;
    render::ShaderProgram program_;
    GLint projectionLocation_ = -1;
    GLuint fontTexture_ = 0;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
};

}  // namespace dropscope::gui
