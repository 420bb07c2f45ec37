#include "render/OffscreenImage.hpp"

namespace dropscope::render {

FramebufferBindings::FramebufferBindings(const GlFunctions& gl) {
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
}

void FramebufferBindings::restore(const GlFunctions& gl) const {
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw));
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
}

OffscreenImage::~OffscreenImage() { release(); }

void OffscreenImage::release() {
    if (framebuffer_ != 0) gl_.DeleteFramebuffers(1, &framebuffer_);
    const GLuint buffers[2] = {colour_, depth_};
    if (colour_ != 0) gl_.DeleteRenderbuffers(2, buffers);
    framebuffer_ = colour_ = depth_ = 0;
    width_ = height_ = 0;
}

bool OffscreenImage::bindForDrawing(int width, int height) {
    if (framebuffer_ != 0 && width == width_ && height == height_) {
        gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        return true;
    }
    const FramebufferBindings caller(gl_);
    release();
    GLint largest = 0;
    gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
    if (width < 1 || height < 1 || width > largest || height > largest) return false;  // nothing bound yet
    GLuint buffers[2] = {0, 0};
    gl_.GenFramebuffers(1, &framebuffer_);
    gl_.GenRenderbuffers(2, buffers);
    colour_ = buffers[0];
    depth_ = buffers[1];
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, colour_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, 0);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        caller.restore(gl_);
        release();
        return false;
    }
    width_ = width;
    height_ = height;
    return true;
}

void OffscreenImage::copyTo(GLuint framebuffer) const {
    const FramebufferBindings caller(gl_);
    const bool scissor = gl_.IsEnabled(GL_SCISSOR_TEST) == GL_TRUE;  // a blit obeys the scissor box
    if (scissor) gl_.Disable(GL_SCISSOR_TEST);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    caller.restore(gl_);
    if (scissor) gl_.Enable(GL_SCISSOR_TEST);
}

}  // namespace dropscope::render
