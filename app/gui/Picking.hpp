#pragma once

#include "gui/AppState.hpp"

#include <optional>

namespace dropscope::gui {

// A shape under the cursor: where the camera ray meets its surface, and the outward normal there.
struct Pick {
    ShapeId shape = RayHit::kNone;
    Point point = Point::Zero();
    Direction normal;
};

// The camera ray through window coordinates (x, y) (logical pixels, top-left origin) of a width x
// height viewport.
Ray cameraRay(const render::Camera& camera, double x, double y, int width, int height);

// Whether the app treats `shape` as a container (a glass cell): drawn translucent, seen through when
// clicked, not dragged, not a surface to drop droplets on. Boxes are; every other shape is a droplet.
bool isContainer(const Shape& shape);

// The first visible shape along the ray, found with the document's octree (Octree::firstHit). Shapes
// the slice plane hides are passed through, and so are boxes when something lies behind them inside:
// boxes are drawn translucent, as containers, so a click means the droplet seen through the glass.
std::optional<Pick> pickShape(const AppState& state, const Ray& ray);

// Where a click in placement mode puts a new droplet's centre: touching the surface under the cursor
// (on the outside, along its normal), else on the placement plane; nullopt when the ray meets neither.
std::optional<Point> placementCenter(const AppState& state, const Ray& ray);

// Where the ray meets the plane normal to coordinate `axis` at `offset` along it (the point's
// coordinate set exactly); nullopt when the ray is parallel to it or it lies behind.
std::optional<Point> rayPlaneAxis(const Ray& ray, int axis, double offset);

// The slice plane of the settings, placed in the scene's bounds; nullopt when off.
std::optional<render::SlicePlane> slicePlane(const SliceSettings& slice);

}  // namespace dropscope::gui
