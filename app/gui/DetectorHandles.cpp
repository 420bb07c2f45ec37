#include "gui/DetectorHandles.hpp"

#include "gui/SourceHandles.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace dropscope::gui {

namespace {

double glyphSize(const Eigen::AlignedBox3d& sceneBounds) {
    return render::kSourceGlyph * sceneBounds.diagonal().norm();
}

// The way a plane's arrow (and aim handle) points: to the side it counts; both sides: along the normal.
Eigen::Vector3d arrowOf(const Detector& plane) {
    return plane.side == DetectorSide::Back ? Eigen::Vector3d(-plane.normal.vector()) : plane.normal.vector();
}

const Detector* selectedDetector(const AppState& state) {
    const auto index = state.scene.selectedDetector();
    return index ? &state.scene.document().detectors()[*index] : nullptr;
}

// `detector`'s up turned by the rotation taking `from` to `to`.
Eigen::Vector3d turnedUp(const Detector& detector, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    return Eigen::Quaterniond::FromTwoVectors(from, to) * detector.up;
}

}  // namespace

std::optional<DetectorHandlePlaces> detectorHandles(const AppState& state, const Eigen::AlignedBox3d& sceneBounds) {
    const Detector* detector = selectedDetector(state);
    if (!state.view.layers.detectors || !detector || sceneBounds.isEmpty()) return std::nullopt;
    const double radius = kHandleMarkerScale * render::kMarkerRadius * sceneBounds.diagonal().norm();
    const double size = glyphSize(sceneBounds);
    switch (detector->type) {
    case DetectorType::Plane:
        return DetectorHandlePlaces{detector->center,
                                    detector->center + render::planeArrowLength(*detector, size) * arrowOf(*detector),
                                    radius};
    case DetectorType::FarField:
        return DetectorHandlePlaces{std::nullopt, render::farFieldGlyphEye(*detector, sceneBounds, size), radius};
    case DetectorType::ShapeAbsorption: break;
    }
    return std::nullopt;
}

DetectorHandle detectorHandleUnder(const AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray) {
    const auto handles = detectorHandles(state, sceneBounds);
    if (!handles) return DetectorHandle::None;
    const double move = handles->move ? distanceToRay(ray, *handles->move) : std::numeric_limits<double>::infinity();
    const double aim = distanceToRay(ray, handles->aim);
    if (std::min(move, aim) > kGrabScale * handles->radius) return DetectorHandle::None;
    return move <= aim ? DetectorHandle::Move : DetectorHandle::Aim;
}

std::optional<Detector> detectorWithHandleAt(const AppState& state, const Eigen::AlignedBox3d& sceneBounds,
                                             DetectorHandle handle, const Point& target) {
    const Detector* selected = selectedDetector(state);
    if (!selected || handle == DetectorHandle::None) return std::nullopt;
    Detector detector = *selected;
    if (detector.type == DetectorType::Plane) {
        if (handle == DetectorHandle::Move) {
            detector.center = target;
            return detector;
        }
        const Direction arrow(target - detector.center);
        if (!arrow) return std::nullopt;
        const Eigen::Vector3d normal = detector.side == DetectorSide::Back ? -arrow.vector() : arrow.vector();
        detector.up = turnedUp(detector, detector.normal.vector(), normal);
        detector.normal = Direction(normal);
        return detector;
    }
    if (detector.type != DetectorType::FarField) return std::nullopt;
    const Direction look(sceneBounds.center() - target);
    if (!look) return std::nullopt;
    detector.up = turnedUp(detector, detector.look.vector(), look.vector());
    detector.look = look;
    return detector;
}

void detectorKey(AppState& state, const Eigen::AlignedBox3d& sceneBounds, DetectorHandle handle,
                 const std::optional<Point>& point) {
    const auto index = state.scene.selectedDetector();
    if (!index) return;
    const Detector& current = state.scene.document().detectors()[*index];
    if (current.type == DetectorType::ShapeAbsorption) {
        return state.ui.status.refuse("a shape-absorption detector has no place or direction");
    }
    if (handle == DetectorHandle::Move && current.type == DetectorType::FarField) {
        return state.ui.status.refuse("a far-field camera is at infinity: A aims it, from the point under the cursor");
    }
    if (!point) return state.ui.status.refuse("nothing under the cursor to move or aim the detector to");
    const auto detector = detectorWithHandleAt(state, sceneBounds, handle, *point);
    if (!detector) return state.ui.status.refuse("the detector is at that point already");
    state.ui.status.attempt("detector not changed", [&] {
        state.scene.document().setDetector(*index, *detector);
        state.ui.status.say(handle == DetectorHandle::Move ? "detector moved to the point under the cursor"
                            : detector->type == DetectorType::Plane
                                ? "detector aimed at the point under the cursor"
                                : "far-field camera looking from the point under the cursor");
    });
}

}  // namespace dropscope::gui
