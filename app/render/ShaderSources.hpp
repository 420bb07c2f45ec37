#pragma once

#include <string_view>
#include <vector>

namespace dropscope::render {

// A GLSL file of shaders/, compiled into the binary (cmake/EmbedShaders.cmake).
struct EmbeddedShader {
    std::string_view file;  // e.g. "impostor.frag"
    std::string_view source;
};

const std::vector<EmbeddedShader>& embeddedShaders();

// The source of shaders/<file>; throws RenderError for a name that was not embedded.
std::string_view shaderSource(std::string_view file);

}  // namespace dropscope::render
