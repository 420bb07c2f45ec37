#pragma once

#include "render/GlFunctions.hpp"

namespace dropscope::render {

// The framebuffers bound for drawing and for reading when made, to bind again.
struct FramebufferBindings {
    explicit FramebufferBindings(const GlFunctions& gl);
    void restore(const GlFunctions& gl) const;

    GLint draw = 0;
    GLint read = 0;
};

// A framebuffer of its own (colour and depth) to draw a picture into once and copy out as often as it is
// needed: ViewportScene keeps the 3D view in one while frames draw the same view, and a screenshot of the
// view alone is drawn into one of its own size (renderViewport).
class OffscreenImage {
public:
    explicit OffscreenImage(const GlFunctions& gl) : gl_(gl) {}
    ~OffscreenImage();
    OffscreenImage(const OffscreenImage&) = delete;
    OffscreenImage& operator=(const OffscreenImage&) = delete;

    // Binds it for reading and drawing at width x height, making it that size first. False when the driver
    // cannot make such a framebuffer; the framebuffers bound before are then bound still, so the caller
    // draws where it would have.
    bool bindForDrawing(int width, int height);
    // Copies the colour drawn into it to `framebuffer` (0: the window's; single-sampled, as a blit from a
    // single-sampled image into a multisampled one of another format is an error), the scissor aside.
    // The framebuffers bound before stay bound.
    void copyTo(GLuint framebuffer) const;

private:
    void release();

    const GlFunctions& gl_;
    GLuint framebuffer_ = 0;
    GLuint colour_ = 0;
    GLuint depth_ = 0;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace dropscope::render
