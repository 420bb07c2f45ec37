#pragma once

#include "scene/SceneView.hpp"

#include <Eigen/Geometry>
#include <glm/glm.hpp>

namespace dropscope::render {

// A perspective camera looking from `eye` at `target`, with orbit, pan and zoom about the target.
// State in double precision (scenes may sit far from the origin); matrices for OpenGL in float.
class Camera {
public:
    glm::dvec3 eye{3.0, 2.1, 4.8};  // a three-quarter view of the origin
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovDeg = 40.0;  // vertical
    double nearPlane = 0.01;
    double farPlane = 100.0;

    bool operator==(const Camera&) const = default;

    static Camera fromView(const SceneView& view);
    SceneView toView() const;

    // Looks at the centre of `bounds` from the current direction, from just far enough for the whole
    // box to fit; near and far planes bracket the box.
    void fitTo(const Eigen::AlignedBox3d& bounds, double aspect);
    // Keeps the near and far planes around `bounds` as the eye moves.
    void clipTo(const Eigen::AlignedBox3d& bounds);

    // Turns the eye about the target: yaw about `up`, pitch about the camera's right axis (radians).
    void orbit(double yaw, double pitch);
    // Moves eye and target together, by fractions of the visible height at the target.
    void pan(double right, double upward);
    // Moves the eye towards the target by `factor` (< 1 closer, > 1 farther).
    void zoom(double factor);

    glm::mat4 viewMatrix() const;
    glm::mat4 projectionMatrix(double aspect) const;
    // Pixel coordinates (x right, y down, origin at the top-left corner) of a world point in an image
    // of width x height, and its depth in [0, 1]; for tests and picking.
    glm::dvec3 project(const glm::dvec3& world, int width, int height) const;
    // The unit direction from the eye through pixel coordinates (x, y) (same convention as project; pixel
    // centres are at half-integers) of a width x height image: the inverse of project, for picking.
    glm::dvec3 rayThrough(double x, double y, int width, int height) const;
};

}  // namespace dropscope::render
