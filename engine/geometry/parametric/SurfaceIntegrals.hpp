#pragma once

#include "geometry/parametric/ParametricSurface.hpp"

#include <Eigen/Core>

namespace dropscope {

struct QuadratureResult {
    double value = 0.0;
    double errorEstimate = 0.0;
};

// Seed 000 eq. 1.67 (m = identity) and 1.68: the integral of |M r_u x M r_v| over the domain, adaptive,
// to about relativeTolerance.
QuadratureResult surfaceAreaIntegral(const ParametricSurface& surface, const Eigen::Matrix3d& m,
                                     double relativeTolerance);

// Seed 000 eq. 1.73: the integral of z (x_u y_v - x_v y_u): the enclosed volume, signed: negative when
// r_u x r_v points inward.
QuadratureResult signedVolumeIntegral(const ParametricSurface& surface, double relativeTolerance);

}  // namespace dropscope
