#pragma once

#include "scene/Scene.hpp"

namespace dropscope {

// Whether `inner` lies inside `outer` in a way the scene accepts as nesting rather than overlap:
// `outer` is a box enclosing `inner`, or both are spheres and |c_outer - c_inner| + r_inner <= r_outer.
bool nestsInside(const Shape& inner, const Shape& outer);

// Throws SceneError at the later of the first two shapes that partly overlap (positive volume of
// intersection, neither nested in the other), naming both. Candidates come from spatial hash grids, one
// per size class of shapes (widths within a factor 8), so a saved scene of 1e6 explicit droplets is
// checked in about a second.
void checkShapesDisjoint(const Scene& scene);

}  // namespace dropscope
