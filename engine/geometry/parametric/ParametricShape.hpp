#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/parametric/ParametricBase.hpp"
#include "geometry/parametric/ParametricClosestPoint.hpp"
#include "geometry/parametric/ParametricRayIntersection.hpp"
#include "geometry/parametric/ParametricSurface.hpp"

#include <Eigen/Geometry>

#include <limits>
#include <memory>
#include <vector>

namespace dropscope {

// A shape bounded by the closed parametric surface M r(u, v) + r0 (seed 000 1.4): a shared base
// (ParametricBase: the surface, its cell tree, mesh, cover, area, volume) placed by an AffineTransform.
class ParametricShape final : public GeneralShape {
public:
    // Throws std::invalid_argument when base is null.
    ParametricShape(std::shared_ptr<const ParametricBase> base, const AffineTransform& transform);

    const std::shared_ptr<const ParametricBase>& base() const { return base_; }
    const ParametricSurface& surface() const { return base_->surface(); }

    ShapeKind kind() const override { return ShapeKind::Parametric; }
    std::string_view typeName() const override { return "parametric"; }

    // Seed 000 eqs. 1.64-1.66 along each row of M, plus r0.
    double xMin() const override { return bounds_.min().x(); }
    double xMax() const override { return bounds_.max().x(); }
    double yMin() const override { return bounds_.min().y(); }
    double yMax() const override { return bounds_.max().y(); }
    double zMin() const override { return bounds_.min().z(); }
    double zMax() const override { return bounds_.max().z(); }

    // Base area times K^2 under a similarity, else eq. 1.68 (computed on first call, shared by copies).
    double surfaceArea() const override;
    // |base signed volume| |det M| (seed 000 1.4.3).
    double volume() const override;
    PointLocation locatePoint(const Point& p) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    std::unique_ptr<Shape> clone() const override { return std::make_unique<ParametricShape>(*this); }
    double surfaceBand() const override { return band_; }

    std::string_view presetName() const override { return surface().presetName(); }
    std::vector<PresetParameter> presetParameters() const override { return surface().presetParameters(); }
    std::unique_ptr<GeneralShape> withTransform(const AffineTransform& transform) const override;

    // The nearest surface point to p among those within `cutoff` (seed 000 eqs. 1.74, 1.75).
    SurfaceProjection closestPoint(const Point& p, double cutoff = std::numeric_limits<double>::infinity()) const;
    // Every crossing of the ray p + s d with s >= sMin, nearest first (ParametricRayIntersection.hpp).
    std::vector<RayCrossing> crossings(const Point& p, const Direction& d, double sMin) const;

protected:
    const SurfaceMesh& baseMesh() const override { return base_->mesh(); }
    const std::vector<Eigen::AlignedBox3d>& baseSurfaceCover() const override { return base_->cover(); }

private:
    struct AreaCache;

    bool withinBand(const Point& p) const;

    std::shared_ptr<const ParametricBase> base_;
    Eigen::AlignedBox3d bounds_;
    double band_ = 0.0;
    std::shared_ptr<AreaCache> area_;  // the non-similarity area, computed once, shared by clones
};

}  // namespace dropscope
