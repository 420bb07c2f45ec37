#pragma once

#include "geometry/Shape.hpp"
#include "scene/Scene.hpp"

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace dropscope {

// Axis-aligned bounds: the shape's xMin()..zMax().
struct Bounds {
    Point min;
    Point max;
};

Bounds boundsOf(const Shape& shape);

// Scene totals for `dropscope inspect`. Volumes and areas are plain sums over the shapes: a shape
// nested inside another counts in full in both.
struct SceneSummary {
    std::map<std::string, std::size_t> shapesByType;  // every known type, zero counts included
    double totalVolume = 0.0;
    double totalSurfaceArea = 0.0;
    std::optional<Bounds> bounds;  // none for a scene without shapes
};

SceneSummary summarise(const Scene& scene);

}  // namespace dropscope
