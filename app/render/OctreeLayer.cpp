#include "render/OctreeLayer.hpp"

#include "render/Colour.hpp"

namespace dropscope::render {

void addOctreeCells(LineBatch& lines, const Octree& octree, const OctreeFilter& filter) {
    using Mode = OctreeFilter::Mode;
    const auto capacity = static_cast<double>(octree.settings().maxShapesPerLeaf);
    octree.visitCells([&](const CellBounds& bounds, int level, bool leaf, std::size_t stored) {
        const bool shown = filter.mode == Mode::All || (filter.mode == Mode::OnlyLevel && level == filter.level) ||
                           (filter.mode == Mode::UpToLevel && level <= filter.level) ||
                           (filter.mode == Mode::LeavesOnly && leaf);
        if (shown) {
            const double occupancy = static_cast<double>(stored) / capacity;
            lines.addBox(bounds, filter.occupancyColour ? viridis(occupancy) : levelColour(level));
        }
        // Deeper cells only matter to the filters that can show them.
        return !(filter.mode == Mode::OnlyLevel || filter.mode == Mode::UpToLevel) || level < filter.level;
    });
}

RayTraversal traceTraversal(const Octree& octree, const Ray& ray) {
    RayTraversal traversal{ray, {}};
    octree.firstHit(ray.origin, ray.direction, traversal.record);
    return traversal;
}

void addTraversal(LineBatch& lines, const RayTraversal& traversal) {
    const TraversalRecord& record = traversal.record;
    for (const CellVisit& cell : record.cells) lines.addBox(cell.bounds, kTraversalColour);
    double end = 0.0;
    if (record.hit) {
        end = record.hit.distance;
    } else if (!record.cells.empty()) {
        end = record.cells.back().tExit;
    }
    if (end > 0.0) {
        const Point& origin = traversal.ray.origin;
        lines.add(origin, origin + end * traversal.ray.direction.vector(), kTraversalColour);
    }
}

}  // namespace dropscope::render
