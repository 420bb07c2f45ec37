#pragma once

#include "gui/AppState.hpp"

#include <optional>

namespace dropscope::gui {

// The selected source's two handles in the 3D view (drawn when the sources layer is on): its origin,
// dragged to move the source, and the tip of its arrow, dragged to aim it.
enum class SourceHandle { None, Origin, Aim };

struct SourceHandlePlaces {
    Point origin;
    Point aim;
    double radius;  // drawn, and grabbed within 1.5 times this
};

inline constexpr render::Colour kOriginHandleColour{1.0f, 1.0f, 1.0f, 1.0f};
inline constexpr render::Colour kAimHandleColour{1.0f, 0.55f, 0.1f, 1.0f};

// A handle is this many event markers across (render::kMarkerRadius): big enough to grab, small beside a
// droplet; it is grabbed within kGrabScale times its radius.
inline constexpr double kHandleMarkerScale = 2.0;
inline constexpr double kGrabScale = 1.5;

// Distance from `point` to the ray, or infinity when the point is behind its origin.
double distanceToRay(const Ray& ray, const Point& point);

// Where the selected source's handles are, sized by the bounds of the shapes drawn; nullopt without
// sources, with the sources layer off, or while a detector is selected (its handles are shown instead).
std::optional<SourceHandlePlaces> sourceHandles(const AppState& state, const Eigen::AlignedBox3d& sceneBounds);

// The handle the ray passes closest to, within grabbing distance, in front of the eye.
SourceHandle handleUnder(const AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray);

}  // namespace dropscope::gui
