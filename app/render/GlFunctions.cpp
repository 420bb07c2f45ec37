#include "render/GlFunctions.hpp"

#include "render/RenderError.hpp"

namespace dropscope::render {

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

}  // namespace dropscope::render
