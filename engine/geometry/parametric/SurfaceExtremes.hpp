#pragma once

#include "geometry/parametric/ParametricSurface.hpp"

#include <Eigen/Core>

namespace dropscope {

struct ExtremeRange {
    double min = 0.0;
    double max = 0.0;
};

// The least and greatest value of direction . r(u, v) over the whole domain (global, not a local
// optimum): projected Newton with alpha*I damping and Armijo backtracking (seed 000 eqs. 1.64-1.66) from
// a grid of starting points.
ExtremeRange extremeRange(const ParametricSurface& surface, const Eigen::Vector3d& direction);

}  // namespace dropscope
