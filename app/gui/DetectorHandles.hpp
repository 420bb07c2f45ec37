#pragma once

#include "gui/AppState.hpp"

#include <optional>

namespace dropscope::gui {

// The selected detector's handles in the 3D view (drawn when the detectors layer is on), as the source's: a
// plane's centre, dragged to move it, and the tip of its normal arrow, dragged to aim it (the arrow the
// glyph draws towards the side it counts); a far-field camera's eye (render::farFieldGlyphEye), dragged
// around the scene to aim it: it then looks from there at the scene's centre. A shape-absorption detector
// has none.
enum class DetectorHandle { None, Move, Aim };

struct DetectorHandlePlaces {
    std::optional<Point> move;  // planes only
    Point aim;
    double radius;  // drawn, and grabbed within 1.5 times this
};

inline constexpr render::Colour kMoveDetectorColour{1.0f, 1.0f, 1.0f, 1.0f};
inline constexpr render::Colour kAimDetectorColour{0.2f, 0.8f, 1.0f, 1.0f};

// Where the selected detector's handles are, sized by the bounds of the shapes drawn; nullopt without a
// selected detector, for one without handles, or with the detectors layer off.
std::optional<DetectorHandlePlaces> detectorHandles(const AppState& state, const Eigen::AlignedBox3d& sceneBounds);

// The handle the ray passes closest to, within grabbing distance, in front of the eye.
DetectorHandle detectorHandleUnder(const AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray);

// The selected detector with `handle` taken to `target`: a plane moved there, or aimed there (its frame turned
// with the normal, so its image does not spin); a far-field camera aimed to look from there at the scene's
// centre (its up turned with it). Nullopt when the target gives no direction.
std::optional<Detector> detectorWithHandleAt(const AppState& state, const Eigen::AlignedBox3d& sceneBounds,
                                             DetectorHandle handle, const Point& target);

// G and A with a detector selected: its handle taken to `point` (the point under the cursor), one undo step,
// what happened in the status line.
void detectorKey(AppState& state, const Eigen::AlignedBox3d& sceneBounds, DetectorHandle handle,
                 const std::optional<Point>& point);

}  // namespace dropscope::gui
