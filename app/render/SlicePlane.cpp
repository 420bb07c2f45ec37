#include "render/SlicePlane.hpp"

#include <cstddef>

namespace dropscope::render {

namespace {

// x + t (y - x), from whichever end is nearer, so t = 0 gives x and t = 1 gives y exactly.
template <class T, class Scalar>
T lerp(const T& x, const T& y, Scalar t) {
    return t < Scalar(0.5) ? T(x + t * (y - x)) : T(y - (Scalar(1) - t) * (y - x));
}

Colour colourAlong(const Colour& a, const Colour& b, double t) {
    Colour out{};
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = lerp(a[k], b[k], static_cast<float>(t));
    return out;
}

Point toPoint(const std::array<float, 3>& p) { return {p[0], p[1], p[2]}; }

// The plane in the anchor's frame, where the drawn positions are.
SlicePlane inAnchorFrame(const SlicePlane& plane, const Anchor& anchor) {
    return {plane.point - anchor.origin, plane.normal};
}

}  // namespace

Point pointAlong(const Point& a, const Point& b, double t) { return lerp(a, b, t); }

std::optional<SegmentSpan> keptSpan(const SlicePlane& plane, const Point& a, const Point& b) {
    if (!plane.normal) return SegmentSpan{};
    const double da = plane.signedDistance(a);
    const double db = plane.signedDistance(b);
    const bool keepA = da <= 0.0;
    const bool keepB = db <= 0.0;
    if (keepA && keepB) return SegmentSpan{};
    if (!keepA && !keepB) return std::nullopt;  // a NaN end counts as hidden
    // The crossing: the signed distance is linear along the segment and vanishes at t.
    const double t = da / (da - db);
    // t = 0 or 1: the kept part is the one end on the plane, a point. A NaN t fails too.
    if (!(t > 0.0 && t < 1.0)) return std::nullopt;
    return keepA ? SegmentSpan{0.0, t} : SegmentSpan{t, 1.0};
}

void appendKeptSegments(LineBatch& out, const LineBatch& lines, const SlicePlane& plane, const Anchor& anchor) {
    const SlicePlane local = inAnchorFrame(plane, anchor);
    const std::vector<LineVertex>& vertices = lines.vertices();
    for (std::size_t k = 0; k + 1 < vertices.size(); k += 2) {
        const LineVertex& va = vertices[k];
        const LineVertex& vb = vertices[k + 1];
        const Point a = toPoint(va.position);
        const Point b = toPoint(vb.position);
        const std::optional<SegmentSpan> span = keptSpan(local, a, b);
        if (!span) continue;
        // Back to world positions for LineBatch::add, which takes the anchor off again. origin + v - origin
        // gives the float v back: v came from p - origin, so origin + v is a double (pinned by
        // SliceLines.APlaneBeyondEverythingLeavesTheLinesAsTheyWere); a kept end is drawn where it was.
        out.add(anchor.origin + pointAlong(a, b, span->from), anchor.origin + pointAlong(a, b, span->to),
                colourAlong(va.colour, vb.colour, span->from), colourAlong(va.colour, vb.colour, span->to));
    }
}

std::vector<ShapeInstance> keptInstances(const std::vector<ShapeInstance>& instances, const SlicePlane& plane,
                                         const Anchor& anchor) {
    const SlicePlane local = inAnchorFrame(plane, anchor);
    std::vector<ShapeInstance> kept;
    for (const ShapeInstance& instance : instances) {
        if (local.keeps(toPoint(instance.center))) kept.push_back(instance);
    }
    return kept;
}

ShapeInstances keptShapes(const ShapeInstances& instances, const std::vector<std::unique_ptr<Shape>>& shapes,
                          const SlicePlane& plane) {
    const auto keep = [&]<class Instance>(const std::vector<Instance>& from, const std::vector<ShapeId>& ids,
                                          std::vector<Instance>& to, std::vector<ShapeId>& toIds) {
        for (std::size_t k = 0; k < from.size(); ++k) {
            if (!plane.keeps(shapes[ids[k]]->bounds().center())) continue;
            to.push_back(from[k]);
            toIds.push_back(ids[k]);
        }
    };
    ShapeInstances kept;
    keep(instances.rounded, instances.roundedIds, kept.rounded, kept.roundedIds);
    keep(instances.boxes, instances.boxIds, kept.boxes, kept.boxIds);
    keep(instances.meshes, instances.meshIds, kept.meshes, kept.meshIds);
    return kept;
}

}  // namespace dropscope::render
