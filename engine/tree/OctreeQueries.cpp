// Point and shape queries: locate (which shape encloses a point) and overlapping (placement checks).
#include "tree/Octree.hpp"

#include <algorithm>

namespace dropscope {

std::optional<ShapeId> Octree::locate(const Point& p) const {
    if (!p.allFinite() || !rootBounds_.contains(p)) return std::nullopt;
    std::optional<ShapeId> innermost;
    const auto consider = [&](ShapeId id) {
        const Shape& s = *shapes_[id];
        if (!s.encloses(p)) return;
        if (!innermost || s.volume() < shapes_[*innermost]->volume() ||
            (s.volume() == shapes_[*innermost]->volume() && id < *innermost)) {
            innermost = id;
        }
    };
    // Down the single path of cells containing p; a shape enclosing p is stored on it.
    std::uint32_t index = 0;
    CellBounds bounds = rootBounds_;
    while (true) {
        const Node& node = nodes_[index];
        for (ShapeId id : node.sphereIds) consider(id);
        for (ShapeId id : node.otherIds) consider(id);
        if (node.isLeaf()) return innermost;
        const Point mid = bounds.center();
        int child = 0;
        for (int axis = 0; axis < 3; ++axis) child |= (p[axis] >= mid[axis] ? 1 : 0) << axis;
        index = node.firstChild + static_cast<std::uint32_t>(child);
        bounds = childBounds(bounds, child);
    }
}

std::vector<ShapeId> Octree::overlapping(const Shape& shape) const {
    const CellBounds extent(Point(shape.xMin(), shape.yMin(), shape.zMin()) .array() - margin_,
                            Point(shape.xMax(), shape.yMax(), shape.zMax()).array() + margin_);
    std::vector<ShapeId> candidates;
    forEachNode([&](std::uint32_t, const Node& node, const CellBounds& bounds) {
        if (!bounds.intersects(extent)) return false;
        candidates.insert(candidates.end(), node.sphereIds.begin(), node.sphereIds.end());
        candidates.insert(candidates.end(), node.otherIds.begin(), node.otherIds.end());
        return true;
    });
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::erase_if(candidates, [&](ShapeId id) { return shapes_[id].get() == &shape || !shapes_[id]->overlaps(shape); });
    return candidates;
}

}  // namespace dropscope
