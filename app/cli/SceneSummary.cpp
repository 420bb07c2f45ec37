#include "cli/SceneSummary.hpp"

#include "tree/Octree.hpp"

namespace dropscope {

SceneSummary summarise(const Scene& scene) {
    SceneSummary summary;
    summary.shapesByType = {{"box", 0}, {"ellipsoid", 0}, {"implicit", 0}, {"parametric", 0}, {"sphere", 0}};
    std::vector<std::unique_ptr<Shape>> copies;
    for (const auto& shape : scene.shapes) {
        copies.push_back(shape->clone());
        ++summary.shapesByType[std::string(shape->typeName())];
        summary.totalVolume += shape->volume();
        summary.totalSurfaceArea += shape->surfaceArea();
        const Eigen::AlignedBox3d bounds = shape->bounds();
        summary.bounds = summary.bounds ? summary.bounds->extend(bounds) : bounds;
    }
    const Octree octree(std::move(copies), scene.octree);
    summary.octree = {scene.octree, octree.rootBounds(), octree.margin(), octree.bytesUsed(), octree.statistics()};
    return summary;
}

}  // namespace dropscope
