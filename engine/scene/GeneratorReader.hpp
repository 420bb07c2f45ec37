#pragma once

#include "scene/JsonReader.hpp"
#include "scene/Scene.hpp"

#include <cstddef>

namespace dropscope {

// Droplets all generators of one scene may make together: about 1 GB of shapes and index.
inline constexpr std::size_t kMaxGeneratedDroplets = 10'000'000;

// The "generators" array (docs/scene-format.md): runs each generator in file order and appends its
// shapes, unnamed, to scene.shapes and scene.shapeNames. Call once the explicit shapes are read and
// checked (scene.explicitShapeCount set): droplets are placed around them.
void readGenerators(const JsonReader& generators, Scene& scene);

}  // namespace dropscope
