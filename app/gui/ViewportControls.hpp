#pragma once

#include "gui/AppState.hpp"
#include "gui/DetectorHandles.hpp"
#include "gui/SourceHandles.hpp"

#include <optional>

namespace dropscope::gui {

// The mouse in the 3D view: orbit, pan, zoom, click to select or place, drag the selected droplet,
// hover tooltip; and the keys that act on the point under the cursor (move or aim a source). Input
// over a panel belongs to the panel (ImGui's WantCaptureMouse).
class ViewportControls {
public:
    // `sceneBounds`: of the shapes as last drawn, which size the source handles (ViewportScene).
    void handle(AppState& state, const Eigen::AlignedBox3d& sceneBounds);

private:
    enum class Drag { None, Pending, Orbit, Pan, MoveShape, MoveHandle };
    void press(AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray);
    void dragTo(AppState& state, const Ray& ray, float dx, float dy);
    void click(AppState& state, const Ray& ray);
    void hover(AppState& state, const Ray& ray);
    void sourceKeys(AppState& state, const Ray& ray);
    void detectorKeys(AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray);
    void moveHandle(AppState& state, const Ray& ray);
    void moveDetectorHandle(AppState& state, const Point& target);

    Drag drag_ = Drag::None;
    float travelled_ = 0.0f;            // pixels moved since the press
    Point grabOffset_ = Point::Zero();  // droplet centre minus the grabbed point on the drag plane
    ShapeId moving_ = RayHit::kNone;
    bool movedThisDrag_ = false;
    SourceHandle handle_ = SourceHandle::None;              // the source handle being dragged
    DetectorHandle detectorHandle_ = DetectorHandle::None;  // or the detector handle
    double handlePlane_ = 0.0;                              // its coordinate along the placement plane's axis
    Eigen::AlignedBox3d handleBounds_;                      // the scene bounds the detector handle was grabbed in
};

}  // namespace dropscope::gui
