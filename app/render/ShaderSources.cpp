#include "render/ShaderSources.hpp"

#include "render/RenderError.hpp"

#include <string>

namespace dropscope::render {

std::string_view shaderSource(std::string_view file) {
    for (const EmbeddedShader& shader : embeddedShaders()) {
        if (shader.file == file) return shader.source;
    }
    throw RenderError("shaders/" + std::string(file) + ": no such shader was built into the program");
}

}  // namespace dropscope::render
