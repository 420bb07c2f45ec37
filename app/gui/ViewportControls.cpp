#include "gui/ViewportControls.hpp"

#include "gui/Actions.hpp"
#include "gui/PanelLayout.hpp"
#include "gui/Picking.hpp"
#include "gui/ShapeDescription.hpp"
#include "gui/SourceReference.hpp"
#include "scene/ShapeSpec.hpp"

#include <imgui.h>

#include <cmath>
#include <sstream>
#include <string>

namespace dropscope::gui {

namespace {

constexpr float kClickTolerance = 4.0f;   // pixels a press may wander and still be a click
constexpr double kOrbitPerPixel = 0.008;  // radians
constexpr double kZoomPerWheelLine = 0.88;

std::string describe(const AppState& state, ShapeId id, const char* separator) {
    const SceneDocument& document = state.scene.document();
    const Shape& shape = *document.octree().shape(id);
    std::ostringstream text;
    text << "shape " << id;
    if (!document.nameOf(id).empty()) text << " \"" << document.nameOf(id) << '"';
    text << separator << shapeTypeLabel(shape) << ", " << document.media().at(shape.mediumId()).name;
    return text.str();
}

// A point for the source keys: on the shape under the cursor, else on the placement plane.
std::optional<Point> pointUnderCursor(const AppState& state, const Ray& ray) {
    if (const auto pick = pickShape(state, ray)) return pick->point;
    return rayPlaneAxis(ray, state.placement.plane.axis, state.placement.plane.offset);
}

}  // namespace

void ViewportControls::handle(AppState& state, const Eigen::AlignedBox3d& sceneBounds) {
    const ImGuiIO& io = ImGui::GetIO();
    const int width = static_cast<int>(io.DisplaySize.x);
    const int height = static_cast<int>(io.DisplaySize.y);
    const bool mouseValid = ImGui::IsMousePosValid(&io.MousePos) && width > 0 && height > 0;
    if (!mouseValid) return;
    render::Camera& camera = state.view.camera;
    const Ray ray = cameraRay(camera, io.MousePos.x, io.MousePos.y, width, height);
    const bool mine = !io.WantCaptureMouse || drag_ != Drag::None;

    if (drag_ == Drag::None && mine) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) press(state, sceneBounds, ray);
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
            drag_ = Drag::Pan;
        }
        if (io.MouseWheel != 0.0f) camera.zoom(std::pow(kZoomPerWheelLine, static_cast<double>(io.MouseWheel)));
    }
    if (drag_ != Drag::None) {
        dragTo(state, ray, io.MouseDelta.x, io.MouseDelta.y);
        const bool held = io.MouseDown[ImGuiMouseButton_Left] || io.MouseDown[ImGuiMouseButton_Right] ||
                          io.MouseDown[ImGuiMouseButton_Middle];
        if (!held) {
            if (drag_ == Drag::Pending) click(state, ray);
            drag_ = Drag::None;
            moving_ = RayHit::kNone;
            handle_ = SourceHandle::None;
            detectorHandle_ = DetectorHandle::None;
        }
    }
    if (mine) {
        hover(state, ray);
        if (!io.WantTextInput && state.ui.prompt == FilePrompt::None) {
            if (state.view.layers.detectors && state.scene.selectedDetector()) {
                detectorKeys(state, sceneBounds, ray);
            } else {
                sourceKeys(state, ray);
            }
        }
    }
}

void ViewportControls::press(AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray) {
    drag_ = Drag::Pending;
    travelled_ = 0.0f;
    handle_ = SourceHandle::None;
    detectorHandle_ = DetectorHandle::None;
    movedThisDrag_ = false;
    if (state.placement.active) return;
    const int axis = state.placement.plane.axis;
    if (const DetectorHandle handle = detectorHandleUnder(state, sceneBounds, ray); handle != DetectorHandle::None) {
        // Grabbed a detector handle: it slides as a source handle does.
        const auto places = detectorHandles(state, sceneBounds);
        const Point at = handle == DetectorHandle::Move ? *places->move : places->aim;
        handlePlane_ = at[axis];
        if (const auto grabbed = rayPlaneAxis(ray, axis, handlePlane_)) {
            grabOffset_ = at - *grabbed;
            detectorHandle_ = handle;
            handleBounds_ = sceneBounds;
        }
        return;
    }
    if (const SourceHandle handle = handleUnder(state, sceneBounds, ray); handle != SourceHandle::None) {
        // Grabbed a source handle: it slides in the plane parallel to the placement plane through it.
        const auto places = sourceHandles(state, sceneBounds);
        const Point at = handle == SourceHandle::Origin ? places->origin : places->aim;
        handlePlane_ = at[axis];
        if (const auto grabbed = rayPlaneAxis(ray, axis, handlePlane_)) {
            grabOffset_ = at - *grabbed;
            handle_ = handle;
        }
        return;
    }
    const ShapeId selected = state.scene.selectedShape();
    if (selected == RayHit::kNone) return;
    const auto pick = pickShape(state, ray);
    const Shape* shape = state.scene.document().octree().shape(selected);
    if (!pick || pick->shape != selected || !shape || isContainer(*shape)) return;
    // Grabbed the selected droplet: it slides in the plane parallel to the placement plane through its centre.
    const ShapeSpec spec = describeShape(*shape);
    if (const auto grabbed = rayPlaneAxis(ray, axis, spec.center[axis])) {
        grabOffset_ = spec.center - *grabbed;
        moving_ = selected;
    }
}

void ViewportControls::dragTo(AppState& state, const Ray& ray, float dx, float dy) {
    travelled_ += std::abs(dx) + std::abs(dy);
    if (drag_ == Drag::Pending && travelled_ > kClickTolerance) {
        drag_ = handle_ != SourceHandle::None || detectorHandle_ != DetectorHandle::None ? Drag::MoveHandle
                : moving_ != RayHit::kNone                                               ? Drag::MoveShape
                                                                                         : Drag::Orbit;
    }
    const ImGuiIO& io = ImGui::GetIO();
    switch (drag_) {
    case Drag::Orbit: state.view.camera.orbit(-kOrbitPerPixel * dx, -kOrbitPerPixel * dy); break;
    case Drag::Pan: state.view.camera.pan(-dx / io.DisplaySize.y, dy / io.DisplaySize.y); break;
    case Drag::MoveShape: {
        const Shape* shape = state.scene.document().octree().shape(moving_);
        if (!shape) break;
        ShapeSpec spec = describeShape(*shape);
        const int axis = state.placement.plane.axis;
        const auto on = rayPlaneAxis(ray, axis, spec.center[axis]);
        if (!on) break;
        spec.center = *on + grabOffset_;
        state.ui.status.attempt("not moved there", [&] {
            // The first move of a drag opens an undo step; the rest of the drag folds into it.
            state.scene.document().modifyShape(moving_, spec, movedThisDrag_);
            movedThisDrag_ = true;
            state.ui.status.say("moving shape " + std::to_string(moving_));
        });
        break;
    }
    case Drag::MoveHandle: moveHandle(state, ray); break;
    default: break;
    }
}

void ViewportControls::moveHandle(AppState& state, const Ray& ray) {
    if (detectorHandle_ != DetectorHandle::None) {
        if (const auto on = rayPlaneAxis(ray, state.placement.plane.axis, handlePlane_)) {
            moveDetectorHandle(state, *on + grabOffset_);
        }
        return;
    }
    std::vector<Source> sources = state.scene.document().sources();
    if (sources.empty()) return;
    Source& source = sources[state.scene.selectedSource()];
    const auto on = rayPlaneAxis(ray, state.placement.plane.axis, handlePlane_);
    if (!on) return;
    const Point target = *on + grabOffset_;
    std::string note;  // what aiming did to the polarisation reference
    if (handle_ == SourceHandle::Origin) {
        source.origin = target;
    } else {
        const Direction direction(target - source.origin);
        if (!direction) return;
        note = aimSource(source, direction);
    }
    state.ui.status.attempt("source not changed", [&] {
        state.scene.document().setSources(std::move(sources), movedThisDrag_);
        movedThisDrag_ = true;
        const std::string done = handle_ == SourceHandle::Origin ? "moving the source" : "aiming the source";
        state.ui.status.say(note.empty() ? done : done + "; " + note);
    });
}

void ViewportControls::moveDetectorHandle(AppState& state, const Point& target) {
    const auto index = state.scene.selectedDetector();
    const auto detector = detectorWithHandleAt(state, handleBounds_, detectorHandle_, target);
    if (!index || !detector) return;
    state.ui.status.attempt("detector not changed", [&] {
        state.scene.document().setDetector(*index, *detector, movedThisDrag_);
        movedThisDrag_ = true;
        state.ui.status.say(detectorHandle_ == DetectorHandle::Move ? "moving the detector" : "aiming the detector");
    });
}

void ViewportControls::click(AppState& state, const Ray& ray) {
    if (state.placement.active) {
        if (const auto center = placementCenter(state, ray)) {
            placeDroplet(state, *center);
        } else {
            state.ui.status.refuse("no surface or placement plane under the cursor");
        }
        return;
    }
    const auto pick = pickShape(state, ray);
    state.scene.selectShape(pick ? pick->shape : RayHit::kNone);
    if (pick) state.ui.status.say("selected " + describe(state, pick->shape, ": "));
}

void ViewportControls::hover(AppState& state, const Ray& ray) {
    if (drag_ == Drag::Orbit || drag_ == Drag::Pan) return;
    if (state.placement.active) {
        const auto center = placementCenter(state, ray);
        ImGui::BeginTooltip();
        if (!center) {
            ImGui::TextUnformatted("no surface or placement plane here");
        } else {
            ShapeSpec spec;
            spec.center = *center;
            spec.radius = state.placement.radius;
            spec.medium = state.placement.medium;
            const auto refusal = state.scene.document().checkPlacement(spec);
            ImGui::Text("droplet r = %g at (%.3g, %.3g, %.3g)", state.placement.radius, center->x(), center->y(),
                        center->z());
            if (refusal) ImGui::TextColored(kErrorColour, "refused: %s", refusal->c_str());
        }
        ImGui::EndTooltip();
        return;
    }
    if (const auto pick = pickShape(state, ray)) ImGui::SetTooltip("%s", describe(state, pick->shape, "\n").c_str());
}

void ViewportControls::detectorKeys(AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray) {
    const bool move = ImGui::IsKeyPressed('G', false);
    const bool aim = ImGui::IsKeyPressed('A', false);
    if (!move && !aim) return;
    detectorKey(state, sceneBounds, move ? DetectorHandle::Move : DetectorHandle::Aim, pointUnderCursor(state, ray));
}

void ViewportControls::sourceKeys(AppState& state, const Ray& ray) {
    const bool move = ImGui::IsKeyPressed('G', false);
    const bool aim = ImGui::IsKeyPressed('A', false);
    if (!move && !aim) return;
    std::vector<Source> sources = state.scene.document().sources();
    if (sources.empty()) return state.ui.status.refuse("no source to move or aim: add one in the Sources panel");
    const auto point = pointUnderCursor(state, ray);
    if (!point) return state.ui.status.refuse("nothing under the cursor to move or aim the source to");
    Source& source = sources[state.scene.selectedSource()];
    std::string note;  // what aiming did to the polarisation reference
    if (move) {
        source.origin = *point;
    } else {
        const Direction direction(*point - source.origin);
        if (!direction) return state.ui.status.refuse("the source is at that point already");
        note = aimSource(source, direction);
    }
    state.ui.status.attempt("source not changed", [&] {
        state.scene.document().setSources(std::move(sources));
        const std::string done =
            move ? "source moved to the point under the cursor" : "source aimed at the point under the cursor";
        state.ui.status.say(note.empty() ? done : done + "; " + note);
    });
}

}  // namespace dropscope::gui
