#pragma once

#include "geometry/AffineTransform.hpp"
#include "scene/JsonReader.hpp"

namespace dropscope {

// A shape's "transform": {"scale", "rotation", "shear", "reflection", "matrix", "translation"}, all
// optional, applied to the base shape in that order (docs/scene-format.md):
//   r -> matrix . reflection . shear . rotation . scale . r + translation.
// scale: a number or [kx, ky, kz], non-zero; rotation: {"axis", "angle_deg"}; shear: {"xy", "xz", "yx",
// "yz", "zx", "zy"} (seed A.6, missing factors 0); reflection: {"normal"} (seed A.3); matrix: 3x3 rows.
// The product must be invertible.
AffineTransform readTransform(const JsonReader& json);

}  // namespace dropscope
