#pragma once

#include "geometry/parametric/ParametricSurface.hpp"

namespace dropscope {

// The torus about the z axis with major radius R and minor radius r (0 < r < R, makeTorusSurface checks):
//   r(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),  u, v in [0, 2 pi],
// u around the z axis, v around the tube; periodic in both. r_u x r_v points outward (its signed volume
// is positive). Preset "torus" {major_radius, minor_radius}.
class TorusSurface final : public ParametricSurface {
public:
    TorusSurface(double majorRadius, double minorRadius);

    double majorRadius() const { return major_; }
    double minorRadius() const { return minor_; }

    ParameterDomain domain() const override;
    Point point(double u, double v) const override;
    SurfaceJet jet(double u, double v) const override;
    SurfaceHessians hessians(double u, double v) const override;

    bool periodicInU() const override { return true; }
    bool periodicInV() const override { return true; }
    double characteristicLength() const override { return 2.0 * (major_ + minor_); }
    std::string_view presetName() const override { return "torus"; }
    std::vector<PresetParameter> presetParameters() const override;

private:
    double major_;
    double minor_;
};

}  // namespace dropscope
