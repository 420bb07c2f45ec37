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

// Where the selected source's handles are, sized by the bounds of the shapes drawn; nullopt without
// sources or with the sources layer off.
std::optional<SourceHandlePlaces> sourceHandles(const AppState& state, const Eigen::AlignedBox3d& sceneBounds);

// The handle the ray passes closest to, within grabbing distance, in front of the eye.
SourceHandle handleUnder(const AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray);

}  // namespace dropscope::gui
