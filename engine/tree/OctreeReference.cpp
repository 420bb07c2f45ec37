// Octree::referenceTree: the fast layout re-expressed in the seed's BoundingBox model.
#include "tree/BoundingBox.hpp"
#include "tree/Octree.hpp"

namespace dropscope {

namespace {

struct Item {
    std::unique_ptr<Shape> shape;
    ShapeId id;
};

// A BoundingBox holding the items; past 8 it keeps 7 and chains the rest into a box of the same bounds.
std::unique_ptr<BoundingBox> group(const CellBounds& bounds, std::vector<Item>& items, std::size_t from = 0) {
    auto box = std::make_unique<BoundingBox>(bounds.min(), bounds.max());
    const std::size_t remaining = items.size() - from;
    const std::size_t direct = remaining <= BoundingBox::kMaxChildren ? remaining : BoundingBox::kMaxChildren - 1;
    for (std::size_t k = from; k < from + direct; ++k) box->addChild(std::move(items[k].shape), items[k].id);
    if (direct < remaining) box->addChild(group(bounds, items, from + direct));
    return box;
}

}  // namespace

std::unique_ptr<BoundingBox> Octree::referenceTree() const {
    // Post-order: a cell's box needs its children's boxes first.
    struct Build {
        const Octree& tree;
        std::unique_ptr<BoundingBox> operator()(std::uint32_t index, const CellBounds& bounds) const {
            const Cell& cell = tree.cells_[index];
            std::vector<Item> items;
            tree.forEachShapeIn(cell, [&](ShapeId id) { items.push_back({tree.shapes_[id]->clone(), id}); });
            if (!cell.isLeaf()) {
                for (int child = 0; child < 8; ++child) {
                    items.push_back(
                        {(*this)(cell.firstChild + static_cast<std::uint32_t>(child), tree.childBounds(bounds, child)),
                         BoundingBox::kNotTerminal});
                }
            }
            return group(bounds, items);
        }
    };
    return Build{*this}(0, rootBounds_);
}

}  // namespace dropscope
