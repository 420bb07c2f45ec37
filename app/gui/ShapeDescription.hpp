#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/Shape.hpp"

#include <Eigen/Core>

#include <array>
#include <string>

namespace dropscope::gui {

// (How a shape is named, "parametric torus": shapeTypeLabel, geometry/GeneralShape.hpp.)

// One preset parameter as the editor shows it, read-only: "1.5" for a number, "(1, 2, 3)" for a short
// vector, the points themselves when there are a few, a count for long lists ("12 points",
// "2 x 4 patches" for bicubic control nets, {rows, columns, 16, 3}).
std::string presetParameterText(const PresetParameter& parameter);

// The rows of a 3x3 matrix, "(1, 0, 0)", for the read-only transform.
std::array<std::string, 3> matrixRows(const Eigen::Matrix3d& m);

}  // namespace dropscope::gui
