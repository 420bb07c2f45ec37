// Point and shape queries: locate (which shape encloses a point), leafHolding, and overlapping (placement
// checks).
#include "tree/Octree.hpp"

#include <algorithm>

namespace dropscope {

std::optional<ShapeId> Octree::locate(const Point& p) const {
    std::optional<ShapeId> innermost;
    forEachShapeAlongPath(p, [&](ShapeId id) {
        const Shape& s = *shapes_[id];
        if (!s.encloses(p)) return;
        if (!innermost || s.volume() < shapes_[*innermost]->volume() ||
            (s.volume() == shapes_[*innermost]->volume() && id < *innermost)) {
            innermost = id;
        }
    });
    return innermost;
}

std::optional<std::uint32_t> Octree::leafHolding(const Point& p) const {
    std::optional<std::uint32_t> leaf;
    forEachCellAlongPath(p, [&](std::uint32_t index) { leaf = index; });
    return leaf;
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
