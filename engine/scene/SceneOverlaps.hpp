#pragma once

#include "scene/Scene.hpp"

namespace dropscope {

// Whether `inner` lies inside `outer` in a way the scene accepts as nesting rather than overlap:
// `outer` is a box enclosing `inner`, or both are spheres and |c_outer - c_inner| + r_inner <= r_outer.
bool nestsInside(const Shape& inner, const Shape& outer);

// Throws SceneError at the later of the first two shapes that partly overlap (positive volume of
// intersection, neither nested in the other), naming both. O(N^2): meant for the explicit shapes of a
// scene file.
void checkShapesDisjoint(const Scene& scene);

}  // namespace dropscope
