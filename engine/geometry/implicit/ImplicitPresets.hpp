#pragma once

#include "geometry/implicit/ImplicitFunction.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace dropscope {

// The implicit presets a scene file can name; each throws std::invalid_argument on bad parameters
// (Superellipsoid.hpp, Blob.hpp).
// "superellipsoid" {semi_axes [a, b, c], exponents [e1, e2]}
std::shared_ptr<const ImplicitFunction> makeSuperellipsoid(const Eigen::Vector3d& semiAxes,
                                                           const Eigen::Vector2d& exponents);
// "blob" {centers [[x, y, z], ...], radii [...], blend}
std::shared_ptr<const ImplicitFunction> makeBlob(const std::vector<Point>& centers, const std::vector<double>& radii,
                                                 double blend);

}  // namespace dropscope
