#pragma once

#include "geometry/Vector.hpp"

namespace dropscope {

// Scene key "view": where the renderer's camera starts (docs/scene-format.md).
struct SceneView {
    Point eye;
    Point target;
    Direction up{0.0, 1.0, 0.0};
    double fovDeg = 40.0;  // vertical field of view
};

}  // namespace dropscope
