// A shader that does not compile is reported with its file and the driver's own log.
#include "render/RenderError.hpp"
#include "render/ShaderProgram.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dropscope {
namespace {

TEST(ShaderProgram, CompileErrorNamesTheFileAndQuotesTheDriversLog) {
    const snapshot::OsmesaContext context(16, 16);
    const std::string broken = "#version 330 core\nout vec4 colour;\nvoid main() { colour = undeclaredThing; }\n";
    try {
        render::ShaderProgram::compile(context.gl(), GL_FRAGMENT_SHADER, "broken.frag", broken);
        FAIL() << "a shader using an undeclared name compiled";
    } catch (const render::RenderError& error) {
        const std::string message = error.what();
        EXPECT_TRUE(message.starts_with("shaders/broken.frag: does not compile: ")) << message;
        // The log is the driver's (Mesa: "0:3(24): error: `undeclaredThing' undeclared"); any compiler
        // names the offending identifier, and the message must carry more than our own prefix.
        EXPECT_NE(message.find("undeclaredThing"), std::string::npos) << message;
        EXPECT_NE(message.find("error"), std::string::npos) << message;
    }
}

TEST(ShaderProgram, ValidSourceCompiles) {
    const snapshot::OsmesaContext context(16, 16);
    const std::string fine = "#version 330 core\nout vec4 colour;\nvoid main() { colour = vec4(1.0); }\n";
    const GLuint shader = render::ShaderProgram::compile(context.gl(), GL_FRAGMENT_SHADER, "fine.frag", fine);
    EXPECT_NE(shader, 0u);
    context.gl().DeleteShader(shader);
}

}  // namespace
}  // namespace dropscope
