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
        const Cell& cell = cells_[index];
        forEachShapeIn(cell, consider);
        if (cell.isLeaf()) return innermost;
        const Point mid = bounds.center();
        int child = 0;
        for (int axis = 0; axis < 3; ++axis) child |= (p[axis] >= mid[axis] ? 1 : 0) << axis;
        index = cell.firstChild + static_cast<std::uint32_t>(child);
        bounds = childBounds(bounds, child);
    }
}

std::vector<ShapeId> Octree::overlapping(const Shape& shape) const {
    const CellBounds shapeBounds = shape.bounds();
    const CellBounds extent(shapeBounds.min().array() - margin_, shapeBounds.max().array() + margin_);
    std::vector<ShapeId> candidates;
    forEachNode([&](std::uint32_t, const Cell& cell, const CellBounds& bounds, int) {
        if (!bounds.intersects(extent)) return false;
        forEachShapeIn(cell, [&](ShapeId id) { candidates.push_back(id); });
        return true;
    });
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::erase_if(candidates, [&](ShapeId id) { return shapes_[id].get() == &shape || !shapes_[id]->overlaps(shape); });
    return candidates;
}

}  // namespace dropscope
