#pragma once

#include "render/GlFunctions.hpp"

#include <string>
#include <string_view>

namespace dropscope::render {

// A linked vertex + fragment program from two files of shaders/. `defines` (lines such as "#define
// POINT_SPRITE\n") go after each file's #version line, for variants of one source. A compile or link error
// throws RenderError with the file name(s) and the driver's log.
class ShaderProgram {
public:
    ShaderProgram(const GlFunctions& gl, std::string_view vertexFile, std::string_view fragmentFile,
                  std::string_view defines = {});
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { gl_.UseProgram(program_); }
    GLint uniform(const char* name) const { return gl_.GetUniformLocation(program_, name); }

    // The compile step alone, exposed for tests of the error message.
    static GLuint compile(const GlFunctions& gl, GLenum stage, std::string_view file, std::string_view source);

private:
    const GlFunctions& gl_;
    GLuint program_ = 0;
};

}  // namespace dropscope::render
