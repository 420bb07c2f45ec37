#pragma once

#include "geometry/Shape.hpp"
#include "render/DrawData.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace dropscope::render {

// A movable plane that hides everything on one side, to look inside a dense cloud (docs/rendering.md).
// The kept side is where (x - point)·normal <= 0: the normal points at what is hidden, and a point
// exactly on the plane is kept. Shapes and markers are kept or hidden whole, by their centre (of their
// bounds, for a parametric or implicit shape): a droplet cut open would show its inside, which the
// impostors cannot draw, and half droplets would read as different shapes. Line segments are cut at the
// plane exactly. A plane with an invalid normal (made from a zero vector) hides nothing.
struct SlicePlane {
    Point point = Point::Zero();
    Direction normal{0.0, 0.0, 1.0};

    // Along the normal from the plane: > 0 hidden, <= 0 kept.
    double signedDistance(const Point& x) const { return normal.dot(x - point); }
    bool keeps(const Point& x) const { return !normal || signedDistance(x) <= 0.0; }

    // The same numbers (so never true of two planes with an invalid normal, whose numbers are NaN).
    bool operator==(const SlicePlane& other) const {
        return point == other.point && normal.vector() == other.normal.vector();
    }
};

// The kept part of a segment a + t (b - a) is t in [from, to], a sub-interval of [0, 1].
struct SegmentSpan {
    double from = 0.0;
    double to = 1.0;
};

// The kept part of segment [a, b]: the whole of it when both ends are kept (a segment in the plane
// included), up to the crossing point when it crosses the plane, and nothing when it is wholly hidden
// or only touches the plane at one end (a point draws nothing).
std::optional<SegmentSpan> keptSpan(const SlicePlane& plane, const Point& a, const Point& b);

// a + t (b - a), exactly a at t = 0 and exactly b at t = 1.
Point pointAlong(const Point& a, const Point& b, double t);

// Appends to `out` the segments of `lines` cut to the kept side: a segment across the plane ends on
// it, its colour interpolated there, and a hidden one is dropped. Both batches use `anchor`; the cut is
// computed in its frame, on the float positions that are drawn.
void appendKeptSegments(LineBatch& out, const LineBatch& lines, const SlicePlane& plane, const Anchor& anchor);

// The instances (markers) whose centre is on the kept side, in the anchor's frame.
std::vector<ShapeInstance> keptInstances(const std::vector<ShapeInstance>& instances, const SlicePlane& plane,
                                         const Anchor& anchor);

// The shape instances (buildShapeInstances of `shapes`) of the shapes whose centre is on the kept side;
// the ids stay parallel to the instances. The centre is that of the shape's bounds, which is the centre
// of a sphere, an ellipsoid and a box, and of the box around a parametric or implicit shape (a mesh is
// kept or hidden whole too, like the droplets, not cut open).
ShapeInstances keptShapes(const ShapeInstances& instances, const std::vector<std::unique_ptr<Shape>>& shapes,
                          const SlicePlane& plane);

}  // namespace dropscope::render
