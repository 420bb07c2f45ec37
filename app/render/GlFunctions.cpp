#include "render/GlFunctions.hpp"

#include "render/RenderError.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace dropscope::render {

namespace {

// Mesa's names for its rasterisers on the processor, as GL_RENDERER gives them (lower case): "llvmpipe (LLVM 15.0.6,
// 256 bits)", "softpipe", "Software Rasterizer" (swrast).
constexpr std::string_view kSoftwareRenderers[] = {"llvmpipe", "softpipe", "software rasterizer"};

}  // namespace

GlFunctions GlFunctions::load(GlProcLoader loader) {
    GlFunctions gl;
#define DROPSCOPE_GL_LOAD(type, name)                     \
    gl.name = reinterpret_cast<type>(loader("gl" #name)); \
    if (!gl.name) throw RenderError("the OpenGL context has no gl" #name);
    DROPSCOPE_GL_FUNCTIONS(DROPSCOPE_GL_LOAD)
#undef DROPSCOPE_GL_LOAD
    return gl;
}

std::string GlFunctions::describe() const {
    const auto text = [&](GLenum name) {
        const auto* value = reinterpret_cast<const char*>(GetString(name));
        return std::string(value ? value : "?");
    };
    return "OpenGL " + text(GL_VERSION) + ", " + text(GL_RENDERER);
}

bool GlFunctions::isSoftware() const {
    const auto* renderer = reinterpret_cast<const char*>(GetString(GL_RENDERER));
    return renderer != nullptr && isSoftwareRenderer(renderer);
}

bool isSoftwareRenderer(std::string_view renderer) {
    std::string lower(renderer);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return std::any_of(std::begin(kSoftwareRenderers), std::end(kSoftwareRenderers),
                       [&](std::string_view name) { return lower.find(name) != std::string::npos; });
}

}  // namespace dropscope::render
