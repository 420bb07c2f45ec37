#include "rendering/DrawCount.hpp"

namespace dropscope::bench {

namespace {

DrawCount gCount;
render::GlFunctions gReal;  // the table the counting functions forward to

void add(GLsizei count, GLsizei instances, bool instanced) {
    const auto n = static_cast<std::uint64_t>(instances);
    ++gCount.calls;
    if (instanced) gCount.instances += n;
    gCount.vertices += n * static_cast<std::uint64_t>(count);
}

void APIENTRY drawArrays(GLenum mode, GLint first, GLsizei count) {
    add(count, 1, false);
    gReal.DrawArrays(mode, first, count);
}

void APIENTRY drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    add(count, 1, false);
    gReal.DrawElements(mode, count, type, indices);
}

void APIENTRY drawArraysInstanced(GLenum mode, GLint first, GLsizei count, GLsizei instances) {
    add(count, instances, true);
    gReal.DrawArraysInstanced(mode, first, count, instances);
}

void APIENTRY drawElementsInstanced(GLenum mode, GLsizei count, GLenum type, const void* indices, GLsizei instances) {
    add(count, instances, true);
    gReal.DrawElementsInstanced(mode, count, type, indices, instances);
}

}  // namespace

DrawCount& drawCount() { return gCount; }

render::GlFunctions countingDraws(const render::GlFunctions& real) {
    gReal = real;
    render::GlFunctions counted = real;
    counted.DrawArrays = drawArrays;
    counted.DrawElements = drawElements;
    counted.DrawArraysInstanced = drawArraysInstanced;
    counted.DrawElementsInstanced = drawElementsInstanced;
    return counted;
}

}  // namespace dropscope::bench
