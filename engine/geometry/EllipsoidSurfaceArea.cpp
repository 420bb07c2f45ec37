#include "geometry/Ellipsoid.hpp"

#include <boost/math/special_functions/ellint_rg.hpp>

#include <numbers>

namespace dropscope {

// S = 4 pi abc R_G(a^-2, b^-2, c^-2) (DLMF 19.33.1). Equivalent to the seed's Legendre form
// (eq. 1.30) but symmetric in a, b, c, so the semi-axes need no sorting and a sphere no special case
// (the seed's form is 0/0 there, docs/geometry.md). R_G(x, x, x) = sqrt(x) gives 4 pi R^2 for a sphere.
double ellipsoidSurfaceArea(const Eigen::Vector3d& semiAxes) {
    const Eigen::Vector3d inverseSquares = semiAxes.cwiseProduct(semiAxes).cwiseInverse();
    return 4.0 * std::numbers::pi * semiAxes.prod() *
           boost::math::ellint_rg(inverseSquares.x(), inverseSquares.y(), inverseSquares.z());
}

}  // namespace dropscope
