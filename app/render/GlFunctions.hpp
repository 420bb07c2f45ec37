#pragma once

#include "render/PixelLayout.hpp"

#include <GL/glcorearb.h>

#include <string>
#include <string_view>

namespace dropscope::render {

// Every OpenGL function the renderer calls, as pointers resolved through the current context's own
// GetProcAddress (glfwGetProcAddress in the GUI, OSMesaGetProcAddress headless). The renderer never
// calls a gl* symbol directly, so one binary can hold both libGL (GLFW's) and libOSMesa without the
// linker choosing whose glClear runs (docs/architecture.md, "OpenGL functions").
#define DROPSCOPE_GL_FUNCTIONS(X)                                \
    X(PFNGLGETSTRINGPROC, GetString)                             \
    X(PFNGLGETERRORPROC, GetError)                               \
    X(PFNGLVIEWPORTPROC, Viewport)                               \
    X(PFNGLCLEARCOLORPROC, ClearColor)                           \
    X(PFNGLCLEARPROC, Clear)                                     \
    X(PFNGLENABLEPROC, Enable)                                   \
    X(PFNGLDISABLEPROC, Disable)                                 \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                             \
    X(PFNGLDEPTHMASKPROC, DepthMask)                             \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                     \
    X(PFNGLFINISHPROC, Finish)                                   \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
    X(PFNGLREADPIXELSPROC, ReadPixels)                           \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
    X(PFNGLBUFFERDATAPROC, BufferData)                           \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
    X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)         \
    X(PFNGLCREATESHADERPROC, CreateShader)                       \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
    X(PFNGLDELETESHADERPROC, DeleteShader)                       \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
    X(PFNGLATTACHSHADERPROC, AttachShader)                       \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                           \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                           \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                             \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                       \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)         \
    X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced)     \
    X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)   \
    X(PFNGLISENABLEDPROC, IsEnabled)                             \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
    X(PFNGLSCISSORPROC, Scissor)                                 \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                     \
    X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate)     \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)             \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                     \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
    X(PFNGLGENTEXTURESPROC, GenTextures)                         \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                     \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)       \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)         \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)

// A function that returns the address of an OpenGL function by name, for the current context.
using GlProcLoader = void* (*)(const char* name);

struct GlFunctions {
#define DROPSCOPE_GL_MEMBER(type, name) type name = nullptr;
    DROPSCOPE_GL_FUNCTIONS(DROPSCOPE_GL_MEMBER)
#undef DROPSCOPE_GL_MEMBER

    // Resolves every function; throws RenderError naming the first one the context does not have.
    static GlFunctions load(GlProcLoader loader);
    // "OpenGL <version>, <renderer>" of the current context, for messages and docs.
    std::string describe() const;
    // Whether the current context's renderer runs on the processor (isSoftwareRenderer of its GL_RENDERER).
    bool isSoftware() const;

    // How the context's window framebuffer (framebuffer 0) lies in memory on a software OpenGL, as the code that
    // made the context knows it; a picture the processor draws for it is handed over in this layout. A wrong
    // guess draws the same picture, more slowly.
    PixelLayout windowLayout;
};

// Whether a GL_RENDERER string names one of Mesa's rasterisers that run on the processor (llvmpipe, softpipe,
// swrast), where drawing a frame of spheres and lines on the processor is faster
// (RenderOptions::processorRaster).
bool isSoftwareRenderer(std::string_view renderer);

}  // namespace dropscope::render
