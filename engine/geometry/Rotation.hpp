#pragma once

#include "geometry/Vector.hpp"

#include <Eigen/Core>

namespace dropscope {

// R = I + Omega sin(theta) + Omega^2 (1 - cos(theta)), seed 000 eq. A.1-A.2.
Eigen::Matrix3d rotationAboutAxis(const Direction& axis, double angleRadians);

}  // namespace dropscope
