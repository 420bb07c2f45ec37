#pragma once

#include "geometry/Shape.hpp"
#include "scene/Scene.hpp"
#include "tree/OctreeTypes.hpp"

#include <vector>

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace dropscope {

// The octree built over the scene's shapes with the scene's settings.
struct OctreeSummary {
    OctreeSettings settings;
    CellBounds root;
    double margin = 0.0;
    std::size_t bytes = 0;
    std::vector<LevelStatistics> levels;
};

// Scene totals for `dropscope inspect`. Volumes and areas are plain sums over the shapes: a shape
// nested inside another counts in full in both.
struct SceneSummary {
    std::map<std::string, std::size_t> shapesByType;  // every known type, zero counts included
    double totalVolume = 0.0;
    double totalSurfaceArea = 0.0;
    std::optional<Eigen::AlignedBox3d> bounds;  // none for a scene without shapes
    OctreeSummary octree;
};

SceneSummary summarise(const Scene& scene);

}  // namespace dropscope
