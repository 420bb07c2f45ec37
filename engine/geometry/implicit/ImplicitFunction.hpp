#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/Vector.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string_view>
#include <vector>

namespace dropscope {

// A base implicit surface f(r) = 0 with f < 0 inside and f > 0 outside (seed 003 1.2.4): what
// transformed implicit shapes f(M^-1 (r - r0)) share (seed 000 Appendix A). f must be Lipschitz: that
// bound is what lets the ray root finder step without jumping over any part of the surface.
class ImplicitFunction {
public:
    virtual ~ImplicitFunction() = default;

    virtual double value(const Point& r) const = 0;
    // grad f; at the rare points where f is not differentiable (a centre, a ridge), any subgradient.
    virtual Eigen::Vector3d gradient(const Point& r) const = 0;

    // L with |f(a) - f(b)| <= L |a - b| for all a, b.
    virtual double lipschitzBound() const = 0;
    // A bound on the rate of change along `direction` (not necessarily unit):
    // |f(r + h direction) - f(r)| <= lipschitzAlong(direction) * |h| for all r, h. Never above
    // L |direction|; presets override it where they know a tighter one.
    virtual double lipschitzAlong(const Eigen::Vector3d& direction) const {
        return lipschitzBound() * direction.norm();
    }

    // When f is a convex function (so the body is convex and f is convex along every line), a point
    // strictly inside the body; nothing otherwise. Convexity is what lets the volume, area and extremes
    // use the cheaper and more accurate routes of ConvexBody.hpp instead of Lipschitz line sweeps.
    virtual std::optional<Point> convexCenter() const { return std::nullopt; }

    // An axis-aligned box certainly containing the whole surface (and so the whole body).
    virtual Eigen::AlignedBox3d bounds() const = 0;

    // The size of the surface's smallest feature (smallest semi-axis, smallest droplet radius): the
    // scale of its surface band.
    virtual double characteristicLength() const = 0;

    // What a scene file names it and the parameters it was built from.
    virtual std::string_view presetName() const = 0;
    virtual std::vector<PresetParameter> presetParameters() const = 0;
};

}  // namespace dropscope
