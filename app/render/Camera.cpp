#include "render/Camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace dropscope::render {

namespace {

glm::dvec3 toGlm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

Camera Camera::fromView(const SceneView& view) {
    Camera camera;
    camera.eye = toGlm(view.eye);
    camera.target = toGlm(view.target);
    camera.up = toGlm(view.up.vector());
    camera.fovDeg = view.fovDeg;
    return camera;
}

SceneView Camera::toView() const {
    return SceneView{Point(eye.x, eye.y, eye.z), Point(target.x, target.y, target.z), Direction(up.x, up.y, up.z),
                     fovDeg};
}

void Camera::fitTo(const Eigen::AlignedBox3d& bounds, double aspect) {
    const glm::dvec3 center = toGlm(bounds.center());
    const double radius = std::max(0.5 * bounds.diagonal().norm(), 1e-9);
    glm::dvec3 direction = eye - target;
    if (glm::length(direction) == 0.0 || !std::isfinite(glm::length(direction))) direction = {3.0, 2.1, 4.8};
    direction = glm::normalize(direction);
    // The bounding sphere fits the narrower of the two fields of view.
    const double halfVertical = glm::radians(fovDeg) / 2.0;
    const double halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const double distance = radius / std::sin(std::min(halfVertical, halfHorizontal));
    target = center;
    eye = center + direction * distance;
    clipTo(bounds);
}

void Camera::clipTo(const Eigen::AlignedBox3d& bounds) {
    const double radius = std::max(0.5 * bounds.diagonal().norm(), 1e-9);
    const double distance = glm::length(eye - toGlm(bounds.center()));
    farPlane = distance + 2.0 * radius;
    nearPlane = std::max(distance - 2.0 * radius, farPlane * 1e-4);
}

void Camera::orbit(double yaw, double pitch) {
    const glm::dvec3 axisUp = glm::normalize(up);
    glm::dvec3 offset = eye - target;
    offset = glm::dmat3(glm::rotate(glm::dmat4(1.0), yaw, axisUp)) * offset;
    const glm::dvec3 right = glm::normalize(glm::cross(-offset, axisUp));
    const glm::dvec3 pitched = glm::dmat3(glm::rotate(glm::dmat4(1.0), pitch, right)) * offset;
    // Stop short of the poles, where `up` and the view direction would become parallel.
    if (std::abs(glm::dot(glm::normalize(pitched), axisUp)) < 0.995) offset = pitched;
    eye = target + offset;
}

void Camera::pan(double right, double upward) {
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 rightAxis = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 upAxis = glm::cross(rightAxis, forward);
    const double height = 2.0 * glm::length(target - eye) * std::tan(glm::radians(fovDeg) / 2.0);
    const glm::dvec3 shift = (rightAxis * right + upAxis * upward) * height;
    eye += shift;
    target += shift;
}

void Camera::zoom(double factor) { eye = target + (eye - target) * factor; }

glm::mat4 Camera::viewMatrix() const { return glm::mat4(glm::lookAt(eye, target, up)); }

glm::mat4 Camera::projectionMatrix(double aspect) const {
    return glm::mat4(glm::perspective(glm::radians(fovDeg), aspect, nearPlane, farPlane));
}

glm::dvec3 Camera::project(const glm::dvec3& world, int width, int height) const {
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const glm::dmat4 clip =
        glm::perspective(glm::radians(fovDeg), aspect, nearPlane, farPlane) * glm::lookAt(eye, target, up);
    const glm::dvec4 p = clip * glm::dvec4(world, 1.0);
    const glm::dvec3 ndc = glm::dvec3(p) / p.w;
    return {(ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height, (ndc.z + 1.0) * 0.5};
}

glm::dvec3 Camera::rayThrough(double x, double y, int width, int height) const {
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 trueUp = glm::cross(right, forward);
    const double tanY = std::tan(glm::radians(fovDeg) / 2.0);
    const double tanX = tanY * static_cast<double>(width) / static_cast<double>(height);
    const double ndcX = 2.0 * x / static_cast<double>(width) - 1.0;
    const double ndcY = 1.0 - 2.0 * y / static_cast<double>(height);
    return glm::normalize(forward + right * (ndcX * tanX) + trueUp * (ndcY * tanY));
}

}  // namespace dropscope::render
