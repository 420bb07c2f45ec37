#include "gui/platform/ImGuiRenderer.hpp"

#include "gui/platform/ImGuiClip.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace dropscope::gui {

namespace {

constexpr const char* kBackendName = "dropscope_gl33";
constexpr GLenum kIndexType = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;

ImTextureID toTextureId(GLuint name) { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(name)); }
GLuint toTextureName(ImTextureID id) { return static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(id)); }

// Every piece of GL state the renderer changes, as it was when constructed; put back on destruction, so
// render() (and the constructor) leave the context as they found it even when a user callback throws.
class SavedGlState {
public:
    explicit SavedGlState(const render::GlFunctions& gl) : gl_(gl) {
        for (std::size_t i = 0; i < kCapabilities.size(); ++i) enabled_[i] = gl.IsEnabled(kCapabilities[i]);
        gl.GetIntegerv(GL_BLEND_EQUATION_RGB, &blendEquationRgb_);
        gl.GetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEquationAlpha_);
        gl.GetIntegerv(GL_BLEND_SRC_RGB, &blendSourceRgb_);
        gl.GetIntegerv(GL_BLEND_DST_RGB, &blendDestinationRgb_);
        gl.GetIntegerv(GL_BLEND_SRC_ALPHA, &blendSourceAlpha_);
        gl.GetIntegerv(GL_BLEND_DST_ALPHA, &blendDestinationAlpha_);
        gl.GetIntegerv(GL_VIEWPORT, viewport_.data());
        gl.GetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
        gl.GetIntegerv(GL_CURRENT_PROGRAM, &program_);
        gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
        gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
        gl.GetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
    }

    ~SavedGlState() {
        for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
            if (enabled_[i]) {
                gl_.Enable(kCapabilities[i]);
            } else {
                gl_.Disable(kCapabilities[i]);
            }
        }
        gl_.BlendEquationSeparate(static_cast<GLenum>(blendEquationRgb_), static_cast<GLenum>(blendEquationAlpha_));
        gl_.BlendFuncSeparate(static_cast<GLenum>(blendSourceRgb_), static_cast<GLenum>(blendDestinationRgb_),
                              static_cast<GLenum>(blendSourceAlpha_), static_cast<GLenum>(blendDestinationAlpha_));
        gl_.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        gl_.Scissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
        gl_.UseProgram(static_cast<GLuint>(program_));
        gl_.BindVertexArray(static_cast<GLuint>(vertexArray_));
        gl_.BindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
        gl_.ActiveTexture(GL_TEXTURE0);
        gl_.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture0_));
        gl_.ActiveTexture(static_cast<GLenum>(activeTexture_));
    }

    SavedGlState(const SavedGlState&) = delete;
    SavedGlState& operator=(const SavedGlState&) = delete;

private:
    static constexpr std::array<GLenum, 4> kCapabilities{GL_BLEND, GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_CULL_FACE};

    const render::GlFunctions& gl_;
    std::array<GLboolean, kCapabilities.size()> enabled_{};
    GLint blendEquationRgb_ = GL_FUNC_ADD;
    GLint blendEquationAlpha_ = GL_FUNC_ADD;
    GLint blendSourceRgb_ = GL_ONE;
    GLint blendDestinationRgb_ = GL_ZERO;
    GLint blendSourceAlpha_ = GL_ONE;
    GLint blendDestinationAlpha_ = GL_ZERO;
    std::array<GLint, 4> viewport_{};
    std::array<GLint, 4> scissorBox_{};
    GLint program_ = 0;
    GLint vertexArray_ = 0;
    GLint arrayBuffer_ = 0;
    GLint activeTexture_ = GL_TEXTURE0;
    GLint texture0_ = 0;  // the 2D texture bound to unit 0
};

}  // namespace

ImGuiRenderer::ImGuiRenderer(const render::GlFunctions& gl)
    : gl_(gl), program_(gl, "imgui.vert", "imgui.frag"), projectionLocation_(program_.uniform("projection")) {
    const SavedGlState saved(gl_);
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = kBackendName;
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;

    // Font atlas: RGBA, linear filtering (ImGui places glyphs at whole pixels; the white pixel is a block).
    unsigned char* pixels = nullptr;
    int width = 0;
    int height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    gl_.GenTextures(1, &fontTexture_);
    gl_.BindTexture(GL_TEXTURE_2D, fontTexture_);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    io.Fonts->SetTexID(toTextureId(fontTexture_));

    // One vertex array: ImDrawVert's position, atlas coordinate and colour (4 normalised bytes).
    gl_.GenVertexArrays(1, &vertexArray_);
    gl_.GenBuffers(1, &vertexBuffer_);
    gl_.GenBuffers(1, &indexBuffer_);
    gl_.BindVertexArray(vertexArray_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    constexpr auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
    const auto attribute = [&](GLuint location, GLint size, GLenum type, GLboolean normalised, std::size_t offset) {
        gl_.EnableVertexAttribArray(location);
        gl_.VertexAttribPointer(location, size, type, normalised, stride, reinterpret_cast<const void*>(offset));
    };
    attribute(0, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, pos));
    attribute(1, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, uv));
    attribute(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(ImDrawVert, col));
}

ImGuiRenderer::~ImGuiRenderer() {
    if (ImGui::GetCurrentContext()) {
        ImGuiIO& io = ImGui::GetIO();
        if (io.Fonts->TexID == fontTexture()) io.Fonts->SetTexID(nullptr);
        if (io.BackendRendererName == kBackendName) {
            io.BackendRendererName = nullptr;
            io.BackendFlags &= ~ImGuiBackendFlags_RendererHasVtxOffset;
        }
    }
    gl_.DeleteBuffers(1, &indexBuffer_);
    gl_.DeleteBuffers(1, &vertexBuffer_);
    gl_.DeleteVertexArrays(1, &vertexArray_);
    gl_.DeleteTextures(1, &fontTexture_);
}

ImTextureID ImGuiRenderer::fontTexture() const { return toTextureId(fontTexture_); }

void ImGuiRenderer::render(const ImDrawData* data) {
    if (!data || data->CmdListsCount == 0) return;
    const int framebufferWidth = static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x);
    const int framebufferHeight = static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y);
    if (framebufferWidth <= 0 || framebufferHeight <= 0) return;  // a minimised window

    const SavedGlState saved(gl_);
    setUpState(*data, framebufferWidth, framebufferHeight);
    upload(*data);
    drawCommands(*data, framebufferWidth, framebufferHeight);
}

void ImGuiRenderer::setUpState(const ImDrawData& data, int framebufferWidth, int framebufferHeight) {
    // Straight alpha blending of colour; alpha accumulates coverage, so an offscreen image of panels over a
    // transparent background keeps their opacity.
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.Viewport(0, 0, framebufferWidth, framebufferHeight);

    // ImGui's display rectangle, y down, onto clip space.
    const float left = data.DisplayPos.x;
    const float top = data.DisplayPos.y;
    const glm::mat4 projection = glm::ortho(left, left + data.DisplaySize.x, top + data.DisplaySize.y, top);
    program_.use();
    gl_.UniformMatrix4fv(projectionLocation_, 1, GL_FALSE, glm::value_ptr(projection));
    gl_.Uniform1i(program_.uniform("atlas"), 0);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindVertexArray(vertexArray_);
}

void ImGuiRenderer::upload(const ImDrawData& data) {
    // Every draw list into one vertex and one index buffer; the old stores are orphaned (BufferData with
    // no data) so this frame's upload never waits for the GPU to finish reading the last one.
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.TotalVtxCount * sizeof(ImDrawVert)), nullptr,
                   GL_STREAM_DRAW);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.TotalIdxCount * sizeof(ImDrawIdx)), nullptr,
                   GL_STREAM_DRAW);
    GLintptr vertexBytes = 0;
    GLintptr indexBytes = 0;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        const auto vertices = static_cast<GLsizeiptr>(list.VtxBuffer.Size * sizeof(ImDrawVert));
        const auto indices = static_cast<GLsizeiptr>(list.IdxBuffer.Size * sizeof(ImDrawIdx));
        gl_.BufferSubData(GL_ARRAY_BUFFER, vertexBytes, vertices, list.VtxBuffer.Data);
        gl_.BufferSubData(GL_ELEMENT_ARRAY_BUFFER, indexBytes, indices, list.IdxBuffer.Data);
        vertexBytes += vertices;
        indexBytes += indices;
    }
}

void ImGuiRenderer::drawCommands(const ImDrawData& data, int framebufferWidth, int framebufferHeight) {
    // Where each list starts in the shared buffers: a command's indices count from its list's first vertex
    // plus its VtxOffset (ImGui splits lists past 64K vertices that way when RendererHasVtxOffset is set).
    GLint listVertex = 0;
    std::size_t listIndex = 0;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList* list = data.CmdLists[n];
        for (const ImDrawCmd& command : list->CmdBuffer) {
            if (command.UserCallback) {
                if (command.UserCallback == ImDrawCallback_ResetRenderState) {
                    setUpState(data, framebufferWidth, framebufferHeight);
                } else {
                    command.UserCallback(list, &command);
                }
                continue;
            }
            const ScissorBox box = scissorBox(data, command.ClipRect, framebufferWidth, framebufferHeight);
            if (box.empty() || command.ElemCount == 0) continue;
            gl_.Scissor(box.x, box.y, box.width, box.height);
            gl_.BindTexture(GL_TEXTURE_2D, toTextureName(command.GetTexID()));
            const std::size_t firstIndex = listIndex + command.IdxOffset;
            gl_.DrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(command.ElemCount), kIndexType,
                                       reinterpret_cast<const void*>(firstIndex * sizeof(ImDrawIdx)),
                                       listVertex + static_cast<GLint>(command.VtxOffset));
        }
        listVertex += list->VtxBuffer.Size;
        listIndex += static_cast<std::size_t>(list->IdxBuffer.Size);
    }
}

}  // namespace dropscope::gui
