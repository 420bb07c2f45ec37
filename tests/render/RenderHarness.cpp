#include "render/RenderHarness.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope::test {

namespace {

render::RenderOptions blackBackground() {
    render::RenderOptions options;
    options.background = {0.0f, 0.0f, 0.0f, 1.0f};
    options.translucentBoxes = false;
    return options;
}

}  // namespace

DirectRenderer::DirectRenderer(int width, int height) : context_(width, height), renderer_(context_.gl()) {}

snapshot::Image DirectRenderer::draw(const render::Camera& camera, const render::Anchor& anchor,
                                     const render::ShapeInstances& shapes, const render::LineBatch& lines,
                                     const std::vector<render::ShapeInstance>& markers) {
    renderer_.setAnchor(anchor);
    renderer_.setShapes(shapes);
    renderer_.setLines(lines);
    renderer_.setMarkers(markers);
    render::RenderOptions options = blackBackground();
    options.pointPixels = pointPixels_;
    options.sphereProgram = sphereProgram_;
    options.apartSpheres = apartSpheres_;
    options.processorRaster = processorRaster_;
    renderer_.draw(camera, options, width(), height(), {}, hold_);
    return context_.read();
}

std::optional<snapshot::Image> DirectRenderer::showHeld() {
    const render::GlFunctions& gl = context_.gl();
    gl.ClearColor(1.0f, 0.0f, 1.0f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    if (!renderer_.showHeld(renderer_.heldPicture(), width(), height(), {})) return std::nullopt;
    return context_.read();
}

render::Camera cameraLookingAt(const Point& eye, const Point& target, double fovDeg,
                               const Eigen::AlignedBox3d& bounds) {
    render::Camera camera;
    camera.eye = {eye.x(), eye.y(), eye.z()};
    camera.target = {target.x(), target.y(), target.z()};
    camera.up = {0.0, 1.0, 0.0};
    camera.fovDeg = fovDeg;
    camera.clipTo(bounds);
    return camera;
}

bool isBlack(const snapshot::Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

bool isLineColour(const snapshot::Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return p[0] == 0 && p[1] == 255 && p[2] == 0;
}

bool samePixel(const snapshot::Image& image, int x, int y, const std::uint8_t* rgba) {
    return std::equal(rgba, rgba + 4, image.pixel(x, y));
}

Eigen::Vector2d projectToPixels(const render::Camera& camera, const Point& world, int width, int height) {
    const glm::dvec3 p = camera.project({world.x(), world.y(), world.z()}, width, height);
    return {p.x, p.y};
}

Direction pixelRay(const render::Camera& camera, int i, int j, int width, int height) {
    const Eigen::Vector3d eye(camera.eye.x, camera.eye.y, camera.eye.z);
    const Eigen::Vector3d target(camera.target.x, camera.target.y, camera.target.z);
    const Eigen::Vector3d up(camera.up.x, camera.up.y, camera.up.z);
    const Eigen::Vector3d forward = (target - eye).normalized();
    const Eigen::Vector3d right = forward.cross(up).normalized();
    const Eigen::Vector3d trueUp = right.cross(forward);
    // The image plane at distance 1: half-height tan(fov / 2), square pixels.
    const double halfHeight = std::tan(camera.fovDeg * std::numbers::pi / 360.0);
    const double pixel = 2.0 * halfHeight / height;
    const double x = (i + 0.5 - 0.5 * width) * pixel;
    const double y = (0.5 * height - (j + 0.5)) * pixel;
    return Direction(forward + x * right + y * trueUp);
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

bool insideImage(const Eigen::Vector2d& point, int width, int height, double margin) {
    return point.x() >= margin && point.y() >= margin && point.x() <= width - margin && point.y() <= height - margin;
}

}  // namespace dropscope::test
