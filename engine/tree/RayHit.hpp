#pragma once

#include "geometry/Shape.hpp"
#include "geometry/Vector.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace dropscope {

using ShapeId = std::uint32_t;

// The nearest surface along a ray: the shape and its distanceToSurface. A distance of 0 (the ray
// leaves the surface it sits on) is not a hit; equal distances go to the lower shape id.
struct RayHit {
    static constexpr ShapeId kNone = std::numeric_limits<ShapeId>::max();
    ShapeId shape = kNone;
    double distance = std::numeric_limits<double>::infinity();

    explicit operator bool() const { return shape != kNone; }

    // Keeps the candidate if it is nearer, or as near with a lower id. NaN and 0 never win.
    void offer(ShapeId id, double t) {
        if (t > 0.0 && (t < distance || (t == distance && id < shape))) {
            shape = id;
            distance = t;
        }
    }
};

// Every shape tested: the definition firstHit must reproduce exactly. Null slots are skipped.
RayHit bruteForceFirstHit(const std::vector<std::unique_ptr<Shape>>& shapes, const Point& p, const Direction& d);

}  // namespace dropscope
