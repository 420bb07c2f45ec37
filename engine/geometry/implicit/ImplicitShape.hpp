#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/implicit/ImplicitBase.hpp"

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

namespace dropscope {

// Everything shared by the shapes built on one implicit function, computed once.
std::shared_ptr<const ImplicitBase> makeImplicitBase(std::shared_ptr<const ImplicitFunction> function);

// The implicit surface f(M^-1 (r - r0)) = 0 (seed 000 Appendix A, seed 003 1.2.4): inside where < 0.
// Distances follow the general-shape semantics (the nearest crossing; a graze is no hit; from the
// surface, the next crossing beyond the ray's own, else 0), found in the base frame along M^-1 d, whose
// parameter is the world distance: by the monotone Newton searches of ConvexRaySearch.hpp when the
// function is convex (a few dozen evaluations even along a flat face), else (or should they fail) by
// RayRootFinder's Lipschitz steps.
//
// locatePoint deviates from the seed's convex two-ray test and from the crossing-parity count of the
// parametric shapes: the sign of f itself says inside or outside, exactly, for any shape; OnSurface
// when the first-order distance estimate |f| / |grad f| (world gradient M^-T grad f) is within the band.
class ImplicitShape final : public GeneralShape {
public:
    // Throws std::invalid_argument on a null base.
    ImplicitShape(std::shared_ptr<const ImplicitBase> base, const AffineTransform& transform);

    const std::shared_ptr<const ImplicitBase>& base() const { return base_; }
    const ImplicitFunction& function() const { return base_->function(); }

    // f of the placed shape at a world point, and its world gradient M^-T grad f.
    double value(const Point& p) const;
    Eigen::Vector3d gradient(const Point& p) const;

    ShapeKind kind() const override { return ShapeKind::Implicit; }
    std::string_view typeName() const override { return "implicit"; }

    // Certified outward bounds (maximumOverBody's upper side): bounds() surely contains the shape,
    // which the octree relies on; at most tolerance::implicit::kExtremeRelative of the diagonal loose.
    double xMin() const override { return extremes()[0]; }
    double xMax() const override { return extremes()[1]; }
    double yMin() const override { return extremes()[2]; }
    double yMax() const override { return extremes()[3]; }
    double zMin() const override { return extremes()[4]; }
    double zMax() const override { return extremes()[5]; }

    // |det M| times the base volume; K^2 times the base area for a similarity, else the radial
    // Gauss-Legendre rule with the placed area element (convex functions, ConvexBody.hpp) or the line
    // integrals (ImplicitBase.hpp) on the placed shape. The estimates carry their error estimates.
    double surfaceArea() const override { return areaEstimate().value; }
    double volume() const override { return volumeEstimate().value; }
    IntegralEstimate areaEstimate() const;
    IntegralEstimate volumeEstimate() const;

    PointLocation locatePoint(const Point& p) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    // One line: "implicit superellipsoid {semi_axes: [a, b, c], exponents: [e1, e2]} M=[[...], ...] r0=(x, y, z)".
    std::unique_ptr<Shape> clone() const override { return std::make_unique<ImplicitShape>(*this); }
    double surfaceBand() const override { return band_; }

    std::string_view presetName() const override { return function().presetName(); }
    std::vector<PresetParameter> presetParameters() const override { return function().presetParameters(); }
    std::unique_ptr<GeneralShape> withTransform(const AffineTransform& transform) const override;

protected:
    const SurfaceMesh& baseMesh() const override { return base_->mesh(); }
    const std::vector<Eigen::AlignedBox3d>& baseSurfaceCover() const override { return base_->surfaceCover(); }

private:
    // distanceToSurface of a point located `start`, in the base frame, over the ray's parameter range in
    // the padded bounds: by the convex searches (nothing when they fail), and by Lipschitz stepping.
    std::optional<double> convexDistance(PointLocation start, const Point& origin, const Eigen::Vector3d& direction,
                                         const std::pair<double, double>& range) const;
    double lipschitzDistance(PointLocation start, const Point& origin, const Eigen::Vector3d& direction,
                             const std::pair<double, double>& range) const;

    // Computed on first use and shared by clones (same base, same transform).
    struct Derived {
        std::once_flag extremesOnce;
        std::array<double, 6> extremes{};
        std::once_flag areaOnce;
        IntegralEstimate area;
    };
    const std::array<double, 6>& extremes() const;

    std::shared_ptr<const ImplicitBase> base_;
    double band_;
    bool convex_;  // the function is convex (ImplicitFunction::convexCentre)
    std::shared_ptr<Derived> derived_;
};

}  // namespace dropscope
