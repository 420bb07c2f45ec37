#pragma once

#include "geometry/Box.hpp"
#include "geometry/SphereGeometry.hpp"
#include "tree/OctreeTypes.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace dropscope {

class BoundingBox;

// The index that finds the next shape a photon meets (seed 000 chapter 2): octants of equal volume
// down to `maxDepth`, leaves of at most `maxShapesPerLeaf` shapes. docs/octree.md has the design.
//
// A shape is stored in every child cell it overlaps, with cells inflated by margin() so that rounding
// can never hide a shape from a ray that grazes a cell boundary; a shape that overlaps all eight
// children of a cell stays in that cell instead (a glass cell around a whole cloud is then tested
// once per ray, not in every leaf). Spheres are also packed by value next to their cell, so the
// hot loop runs SphereGeometry on contiguous memory, the same code as Sphere itself.
class Octree {
public:
    explicit Octree(std::vector<std::unique_ptr<Shape>> shapes, OctreeSettings settings = {});
    ~Octree();
    Octree(Octree&&) noexcept;
    Octree& operator=(Octree&&) noexcept;

    // Ids are positions in the vector the octree was built from, then insertion order. A removed
    // shape leaves an empty slot, so ids never change.
    std::size_t slotCount() const { return shapes_.size(); }
    std::size_t shapeCount() const { return liveShapes_; }
    const Shape* shape(ShapeId id) const { return id < shapes_.size() ? shapes_[id].get() : nullptr; }
    const std::vector<std::unique_ptr<Shape>>& shapes() const { return shapes_; }
    const OctreeSettings& settings() const { return settings_; }
    const CellBounds& rootBounds() const { return rootBounds_; }
    double margin() const { return margin_; }

    // The nearest surface along the ray, exactly as bruteForceFirstHit.
    RayHit firstHit(const Point& p, const Direction& d) const;
    RayHit firstHit(const Point& p, const Direction& d, TraversalRecord& record) const;
    // The innermost shape (smallest volume) that encloses p, if any.
    std::optional<ShapeId> locate(const Point& p) const;
    // Ids of the stored shapes that overlap `shape` (Shape::overlaps), ascending.
    std::vector<ShapeId> overlapping(const Shape& shape) const;

    ShapeId insert(std::unique_ptr<Shape> shape);
    std::unique_ptr<Shape> remove(ShapeId id);

    std::vector<LevelStatistics> statistics() const;
    std::size_t bytesUsed() const;

    // The seed's node model: a BoundingBox per cell holding at most 8 children. For tests and the
    // debugger; the flat arrays here stay the source of truth.
    std::unique_ptr<BoundingBox> referenceTree() const;

private:
    static constexpr std::uint32_t kNoChild = 0;  // node 0 is the root, never anyone's child

    struct Node {
        std::uint32_t firstChild = kNoChild;  // the 8 children are consecutive
        std::uint32_t level = 0;
        std::vector<SphereGeometry> spheres;  // packed copies of the sphere ids below
        std::vector<ShapeId> sphereIds;
        std::vector<ShapeId> otherIds;        // boxes, ellipsoids, anything else
        bool isLeaf() const { return firstChild == kNoChild; }
        std::size_t size() const { return sphereIds.size() + otherIds.size(); }
    };

    struct Traversal;

    void rebuild(const CellBounds& bounds);
    void place(std::uint32_t node, const CellBounds& bounds, ShapeId id);
    void store(Node& node, ShapeId id);
    void split(std::uint32_t node, const CellBounds& bounds);
    bool reaches(const Shape& shape, const CellBounds& cell) const;
    void unstore(std::uint32_t node, const CellBounds& bounds, ShapeId id);
    CellBounds childBounds(const CellBounds& bounds, int child) const;
    // Depth first from the root; `visit(index, node, bounds)` returns whether to descend.
    template <class Visit>
    void forEachNode(Visit&& visit) const;

    std::vector<std::unique_ptr<Shape>> shapes_;
    std::size_t liveShapes_ = 0;
    OctreeSettings settings_;
    CellBounds rootBounds_;
    double margin_ = 0.0;
    std::vector<Node> nodes_;
};

template <class Visit>
void Octree::forEachNode(Visit&& visit) const {
    struct Pending {
        std::uint32_t node;
        CellBounds bounds;
    };
    std::vector<Pending> stack{{0, rootBounds_}};
    while (!stack.empty()) {
        const Pending top = stack.back();
        stack.pop_back();
        const Node& n = nodes_[top.node];
        if (!visit(top.node, n, top.bounds) || n.isLeaf()) continue;
        for (int child = 7; child >= 0; --child)
            stack.push_back({n.firstChild + static_cast<std::uint32_t>(child), childBounds(top.bounds, child)});
    }
}

}  // namespace dropscope
