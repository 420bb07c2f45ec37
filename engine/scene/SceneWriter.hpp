#pragma once

#include "scene/Scene.hpp"

#include <iosfwd>
#include <string>

namespace dropscope {

// Writes `scene` as a scene file of format version 1 (docs/scene-format.md) that loadScene reads back to
// the same scene: unit, wavelength, ambient, every medium in id order (the loader's built-in vacuum
// too, so the ids stay), every shape as an explicit shape in id order (generated droplets included, so
// no generators are written; names kept), sources, octree settings and the view when set. Numbers are
// written in the shortest form that reads back as the same double. Spheres and boxes reload exactly;
// an ellipsoid is written as centre, semi-axes and rotation and reloads with the same matrix up to
// rounding (~1e-15 relative). Two-space indents, one medium, shape or source per line.
//
// Throws std::invalid_argument for a scene no file could express: a null shape, a medium id out of
// range, an empty or repeated medium name, a repeated shape name.
void writeScene(const Scene& scene, std::ostream& out);

// The same text as a string.
std::string sceneToJson(const Scene& scene);

}  // namespace dropscope
