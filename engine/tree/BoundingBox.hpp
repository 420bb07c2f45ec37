#pragma once

#include "geometry/Box.hpp"
#include "tree/RayHit.hpp"

#include <memory>
#include <vector>

namespace dropscope {

// The seed's octree node (seed 000 chapter 2, seed 001 "BoundingBox"): an axis-aligned box holding
// at most 8 children, each either a deeper BoundingBox or a terminal shape. Terminal children keep
// the id of the shape they copy. Octree::referenceTree() builds this model from the fast layout; it
// is the reference the fast traversal is tested against, and what the debugger can walk.
class BoundingBox : public Box {
public:
    static constexpr std::size_t kMaxChildren = 8;
    static constexpr ShapeId kNotTerminal = RayHit::kNone;

    BoundingBox(const Point& lower, const Point& upper) : Box(lower, upper) {}

    // Throws std::length_error past kMaxChildren.
    void addChild(std::unique_ptr<Shape> child, ShapeId terminalId = kNotTerminal);
    std::size_t childCount() const { return children_.size(); }
    const Shape& child(std::size_t k) const { return *children_[k]; }
    // The shape id of a terminal child; kNotTerminal for a BoundingBox.
    ShapeId childId(std::size_t k) const { return childIds_[k]; }

    // Whether `other` overlaps any terminal shape inside this box (seed 001 item 8).
    bool contentsOverlap(const Shape& other) const;

    // Every terminal child reached by descending into the boxes the ray meets (inflated by
    // `margin`), with no early exit: the reference for Octree::firstHit.
    RayHit firstHit(const Point& p, const Direction& d, double margin) const;

    std::unique_ptr<Shape> clone() const override;
    void print(std::ostream& os) const override;

private:
    void collectHits(const Point& p, const Direction& d, double margin, RayHit& hit) const;

    std::vector<std::unique_ptr<Shape>> children_;
    std::vector<ShapeId> childIds_;
};

}  // namespace dropscope
