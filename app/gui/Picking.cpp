#include "gui/Picking.hpp"

namespace dropscope::gui {

namespace {

// Surfaces crossed before a pick gives up: each hidden or container shape costs one or two.
constexpr int kMaxPickCrossings = 64;

bool hiddenBySlice(const AppState& state, const Shape& shape) {
    const auto plane = slicePlane(state.view.slice);
    return plane && !plane->keeps(shape.bounds().center());
}

}  // namespace

Ray cameraRay(const render::Camera& camera, double x, double y, int width, int height) {
    const glm::dvec3 d = camera.rayThrough(x, y, width, height);
    return Ray{Point(camera.eye.x, camera.eye.y, camera.eye.z), Direction(d.x, d.y, d.z)};
}

bool isContainer(const Shape& shape) { return shape.kind() == ShapeKind::Box; }

std::optional<Pick> pickShape(const AppState& state, const Ray& ray) {
    const Octree& octree = state.scene.document().octree();
    std::optional<Pick> container;
    Point from = ray.origin;
    for (int crossing = 0; crossing < kMaxPickCrossings; ++crossing) {
        const RayHit hit = octree.firstHit(from, ray.direction);
        if (!hit) break;
        const Shape& shape = *octree.shape(hit.shape);
        const Point point = from + hit.distance * ray.direction.vector();
        from = point;
        if (hiddenBySlice(state, shape)) continue;
        if (isContainer(shape)) {
            if (!container) container = Pick{hit.shape, point, shape.normal(point)};
            continue;
        }
        return Pick{hit.shape, point, shape.normal(point)};
    }
    return container;
}

std::optional<Point> placementCenter(const AppState& state, const Ray& ray) {
    if (const auto pick = pickShape(state, ray);
        pick && pick->normal && !isContainer(*state.scene.document().octree().shape(pick->shape))) {
        return Point(pick->point + state.placement.radius * pick->normal.vector());
    }
    return rayPlaneAxis(ray, state.placement.plane.axis, state.placement.plane.offset);
}

std::optional<Point> rayPlaneAxis(const Ray& ray, int axis, double offset) {
    const double along = ray.direction[axis];
    if (along == 0.0) return std::nullopt;
    const double t = (offset - ray.origin[axis]) / along;
    if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
    Point p = ray.origin + t * ray.direction.vector();
    p[axis] = offset;  // exactly on the plane, whatever the rounding
    return p;
}

std::optional<render::SlicePlane> slicePlane(const SliceSettings& slice) {
    if (!slice.enabled) return std::nullopt;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    normal[slice.axis] = slice.flip ? -1.0 : 1.0;
    Point point = Point::Zero();
    point[slice.axis] = slice.offset;
    return render::SlicePlane{point, Direction(normal)};
}

}  // namespace dropscope::gui
