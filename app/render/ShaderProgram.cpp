#include "render/ShaderProgram.hpp"

#include "render/RenderError.hpp"
#include "render/ShaderSources.hpp"

#include <string>
#include <vector>

namespace dropscope::render {

namespace {

template <class GetLength, class GetLog>
std::string infoLog(GLuint object, GetLength getLength, GetLog getLog) {
    GLint length = 0;
    getLength(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    getLog(object, static_cast<GLsizei>(text.size()), nullptr, text.data());
    std::string log(text.data());
    while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) log.pop_back();
    return log;
}

// The source with `defines` after its first line (#version must come first).
std::string withDefines(std::string_view source, std::string_view defines) {
    if (defines.empty()) return std::string(source);
    const std::size_t lineEnd = source.find('\n');
    const std::size_t split = lineEnd == std::string_view::npos ? source.size() : lineEnd + 1;
    std::string out(source.substr(0, split));
    if (lineEnd == std::string_view::npos) out += '\n';
    out += defines;
    out += "#line 2\n";  // the driver's messages keep the file's own line numbers
    out += source.substr(split);
    return out;
}

}  // namespace

GLuint ShaderProgram::compile(const GlFunctions& gl, GLenum stage, std::string_view file, std::string_view source) {
    const GLuint shader = gl.CreateShader(stage);
    const GLchar* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    gl.ShaderSource(shader, 1, &text, &length);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = infoLog(shader, gl.GetShaderiv, gl.GetShaderInfoLog);
        gl.DeleteShader(shader);
        throw RenderError("shaders/" + std::string(file) + ": does not compile: " + log);
    }
    return shader;
}

ShaderProgram::ShaderProgram(const GlFunctions& gl, std::string_view vertexFile, std::string_view fragmentFile,
                             std::string_view defines)
    : gl_(gl) {
    const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertexFile, withDefines(shaderSource(vertexFile), defines));
    GLuint fragment = 0;
    try {
        fragment = compile(gl, GL_FRAGMENT_SHADER, fragmentFile, withDefines(shaderSource(fragmentFile), defines));
    } catch (...) {
        gl.DeleteShader(vertex);
        throw;
    }
    program_ = gl.CreateProgram();
    gl.AttachShader(program_, vertex);
    gl.AttachShader(program_, fragment);
    gl.LinkProgram(program_);
    gl.DeleteShader(vertex);
    gl.DeleteShader(fragment);
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = infoLog(program_, gl.GetProgramiv, gl.GetProgramInfoLog);
        gl.DeleteProgram(program_);
        throw RenderError("shaders/" + std::string(vertexFile) + " + shaders/" + std::string(fragmentFile) +
                          ": do not link: " + log);
    }
}

ShaderProgram::~ShaderProgram() { gl_.DeleteProgram(program_); }

}  // namespace dropscope::render
