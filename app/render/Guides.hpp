#pragma once

#include "render/DrawData.hpp"

namespace dropscope::render {

inline constexpr Colour kAxisX{0.95f, 0.25f, 0.25f, 1.0f};
inline constexpr Colour kAxisY{0.30f, 0.85f, 0.30f, 1.0f};
inline constexpr Colour kAxisZ{0.30f, 0.50f, 1.00f, 1.0f};
inline constexpr Colour kGridColour{0.32f, 0.34f, 0.38f, 1.0f};

// The coordinate axes from `origin`, each `length` long: x red, y green, z blue.
void addAxes(LineBatch& lines, const Point& origin, double length);

// A square ground grid under `bounds`: in the plane perpendicular to the coordinate axis nearest `up`
// (so its lines follow the other two axes), just below the bounds' lowest point along `up`, centred
// under them and 1.5 times their larger extent across, with a 1-2-5 spacing giving about ten cells a
// side and lines on whole multiples of the spacing.
void addGroundGrid(LineBatch& lines, const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& up);

}  // namespace dropscope::render
