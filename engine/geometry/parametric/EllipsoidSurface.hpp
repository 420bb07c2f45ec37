#pragma once

#include "geometry/parametric/ParametricSurface.hpp"

#include <Eigen/Core>

namespace dropscope {

// The axis-aligned ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 in the seed's octant parametrisation
// (seed 000 1.3.2, before eq. 1.33) extended to the whole surface:
//   r(u, v) = a sqrt(1 - u^2) cos v x + b sqrt(1 - u^2) sin v y + c u z,  u in [-1, 1], v in [0, 2 pi],
// periodic in v, with poles at u = -1, 1. As in the seed, r_u x r_v points inward (its signed volume is
// negative). Rotations come from the shape's transform. Presets "sphere" {radius} and "ellipsoid"
// {semi_axes}. The semi-axes must be finite and > 0 (makeSphereSurface / makeEllipsoidSurface check).
class EllipsoidSurface final : public ParametricSurface {
public:
    enum class Preset { Sphere, Ellipsoid };

    EllipsoidSurface(const Eigen::Vector3d& semiAxes, Preset preset);

    const Eigen::Vector3d& semiAxes() const { return semiAxes_; }

    ParameterDomain domain() const override;
    Point point(double u, double v) const override;
    // At the poles |u| = 1, where d sqrt(1 - u^2) / du is unbounded, jet and hessians return the finite
    // part of each derivative: the terms carrying (sqrt(1 - u^2))' or '' are dropped, so r_u = (0, 0, c)
    // and r_uu = r_uv = 0 there (r_v = r_vv = 0 anyway). r_u x r_v is then 0, the measure-zero value
    // a quadrature never samples; everywhere else the derivatives are exact.
    SurfaceJet jet(double u, double v) const override;
    SurfaceHessians hessians(double u, double v) const override;

    bool periodicInV() const override { return true; }
    double characteristicLength() const override;
    std::string_view presetName() const override;
    std::vector<PresetParameter> presetParameters() const override;

private:
    Eigen::Vector3d semiAxes_;
    Preset preset_;
};

}  // namespace dropscope
