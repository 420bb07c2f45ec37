#include "render/OffscreenImage.hpp"

namespace dropscope::render {

OffscreenImage::~OffscreenImage() { release(); }

void OffscreenImage::release() {
    if (framebuffer_ != 0) gl_.DeleteFramebuffers(1, &framebuffer_);
    const GLuint buffers[2] = {colour_, depth_};
    if (colour_ != 0) gl_.DeleteRenderbuffers(2, buffers);
    framebuffer_ = colour_ = depth_ = 0;
    width_ = height_ = 0;
}

bool OffscreenImage::bindForDrawing(int width, int height) {
    if (framebuffer_ == 0 || width != width_ || height != height_) {
        release();
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
            gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
            release();
            return false;
        }
        width_ = width;
        height_ = height;
        return true;
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    return true;
}

void OffscreenImage::copyTo(GLuint framebuffer) const {
    const bool scissor = gl_.IsEnabled(GL_SCISSOR_TEST) == GL_TRUE;  // a blit obeys the scissor box
    if (scissor) gl_.Disable(GL_SCISSOR_TEST);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    if (scissor) gl_.Enable(GL_SCISSOR_TEST);
}

}  // namespace dropscope::render
