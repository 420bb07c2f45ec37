#include "render/Layers.hpp"

namespace dropscope::render {

void addOctreeCells(LineBatch& lines, const Octree& octree, const OctreeFilter& filter) {
    octree.visitCells([&](const CellBounds& bounds, int level, bool leaf, std::size_t stored) {
        using Mode = OctreeFilter::Mode;
        const bool shown = filter.mode == Mode::All || (filter.mode == Mode::OnlyLevel && level == filter.level) ||
                           (filter.mode == Mode::UpToLevel && level <= filter.level) ||
                           (filter.mode == Mode::LeavesOnly && leaf);
        if (shown) {
            const double heat = static_cast<double>(stored) / static_cast<double>(octree.settings().maxShapesPerLeaf);
            lines.addBox(bounds, filter.occupancyColour ? viridis(heat) : levelColour(level));
        }
        return !(filter.mode == Mode::OnlyLevel || filter.mode == Mode::UpToLevel) || level < filter.level;
    });
}

void addPhotonPaths(LineBatch& lines, const std::vector<PhotonPath>& paths, double escapeLength) {
    for (const PhotonPath& path : paths) {
        for (std::size_t k = 0; k + 1 < path.events.size(); ++k) {
            lines.add(path.events[k].position, path.events[k + 1].position, viridis(path.events[k].weight));
        }
        const Event& last = path.events.back();
        if (last.type == EventType::Escape) {
            lines.add(last.position, last.position + escapeLength * last.direction.vector(), viridis(last.weight));
        }
    }
}

}  // namespace dropscope::render
