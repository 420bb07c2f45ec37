#pragma once

#include "render/Camera.hpp"
#include "render/DrawData.hpp"
#include "render/Renderer.hpp"
#include "snapshot/Image.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <Eigen/Core>

#include <cmath>
#include <optional>

namespace dropscope::test {

// Lines drawn by the tests: pure green, written exactly (no lighting, no blending) onto black.
inline constexpr render::Colour kLineColour{0.0f, 1.0f, 0.0f, 1.0f};

// An OSMesa context and a renderer that draws onto a black background, opaque shapes only: the
// renderer on its own, without the snapshot's choices of camera, layers and colours.
class DirectRenderer {
public:
    DirectRenderer(int width, int height);

    snapshot::Image draw(const render::Camera& camera, const render::Anchor& anchor,
                         const render::ShapeInstances& shapes, const render::LineBatch& lines,
                         const std::vector<render::ShapeInstance>& markers = {});
    // RenderOptions::pointPixels of the next draws (0, every shape exact, unless set).
    void setPointPixels(float pixels) { pointPixels_ = pixels; }
    // RenderOptions::sphereProgram of the next draws (on unless set).
    void setSphereProgram(bool on) { sphereProgram_ = on; }
    // RenderOptions::apartSpheres of the next draws (on unless set).
    void setApartSpheres(bool on) { apartSpheres_ = on; }
    // RenderOptions::processorRaster of the next draws (off unless set).
    void setProcessorRaster(bool on) { processorRaster_ = on; }
    // What the renderer takes the framebuffer's layout to be (OSMesa's own, the top row first in RGBA, unless set).
    void setWindowLayout(render::PixelLayout layout) { context_.setWindowLayout(layout); }
    // Whether the next draws hold their picture drawn on the processor (Renderer::draw's `hold`; off unless set).
    void setHold(bool on) { hold_ = on; }
    // The framebuffer cleared to magenta, then the held picture shown again (Renderer::showHeld), read back; none
    // when the renderer declines.
    std::optional<snapshot::Image> showHeld();
    // Renderer::apartInLastFrame and lastFrameOnProcessor of the last draw.
    std::size_t apartInLastFrame() const { return renderer_.apartInLastFrame(); }
    bool lastFrameOnProcessor() const { return renderer_.lastFrameOnProcessor(); }
    int width() const { return context_.width(); }
    int height() const { return context_.height(); }

private:
    snapshot::OsmesaContext context_;
    render::Renderer renderer_;
    float pointPixels_ = 0.0f;
    bool sphereProgram_ = true;
    bool apartSpheres_ = true;
    bool processorRaster_ = false;
    bool hold_ = false;
};

// A camera from `eye` to `target`, up +y, with its near and far planes around `bounds`.
render::Camera cameraLookingAt(const Point& eye, const Point& target, double fovDeg, const Eigen::AlignedBox3d& bounds);

// Background: black in every colour channel (a shaded shape keeps at least 30 % of its colour).
bool isBlack(const snapshot::Image& image, int x, int y);
bool isLineColour(const snapshot::Image& image, int x, int y);
bool samePixel(const snapshot::Image& image, int x, int y, const std::uint8_t* rgba);

// Camera::project's x and y: pixel coordinates, origin at the image's top-left corner.
Eigen::Vector2d projectToPixels(const render::Camera& camera, const Point& world, int width, int height);

// The eye ray through the centre of pixel (i, j), from the pinhole model the camera stands for (look-at
// basis, vertical field of view, square pixels), written out here independently of the GL matrices.
Direction pixelRay(const render::Camera& camera, int i, int j, int width, int height);

// Whether a pixel within `reach` (Chebyshev distance) of the pixel holding `point` satisfies `lit`
// (which answers false outside the image).
template <class Lit>
bool litNear(const Eigen::Vector2d& point, int reach, Lit lit) {
    const int cx = static_cast<int>(std::floor(point.x()));
    const int cy = static_cast<int>(std::floor(point.y()));
    for (int y = cy - reach; y <= cy + reach; ++y) {
        for (int x = cx - reach; x <= cx + reach; ++x) {
            if (lit(x, y)) return true;
        }
    }
    return false;
}

// Whether (x, y) is a pixel of the image.
inline bool inImage(const snapshot::Image& image, int x, int y) {
    return x >= 0 && y >= 0 && x < image.width && y < image.height;
}

// Distance from p to the segment [a, b] in the image plane.
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// Whether the pixel centre (i + 0.5, j + 0.5) lies inside the image's margin-shrunk frame.
bool insideImage(const Eigen::Vector2d& point, int width, int height, double margin);

}  // namespace dropscope::test
