#include "cli/SceneSummary.hpp"

#include "tree/Octree.hpp"

namespace dropscope {

Bounds boundsOf(const Shape& shape) {
    return {Point(shape.xMin(), shape.yMin(), shape.zMin()), Point(shape.xMax(), shape.yMax(), shape.zMax())};
}

SceneSummary summarise(const Scene& scene) {
    SceneSummary summary;
    summary.shapesByType = {{"box", 0}, {"ellipsoid", 0}, {"sphere", 0}};
    for (const auto& shape : scene.shapes) {
        ++summary.shapesByType[std::string(shape->typeName())];
        summary.totalVolume += shape->volume();
        summary.totalSurfaceArea += shape->surfaceArea();
        const Bounds bounds = boundsOf(*shape);
        if (!summary.bounds) {
            summary.bounds = bounds;
        } else {
            summary.bounds->min = summary.bounds->min.cwiseMin(bounds.min);
            summary.bounds->max = summary.bounds->max.cwiseMax(bounds.max);
        }
    }
    std::vector<std::unique_ptr<Shape>> copies;
    for (const auto& shape : scene.shapes) copies.push_back(shape->clone());
    const Octree octree(std::move(copies), scene.octree);
    summary.octree = {scene.octree, octree.rootBounds(), octree.margin(), octree.bytesUsed(), octree.statistics()};
    return summary;
}

}  // namespace dropscope
