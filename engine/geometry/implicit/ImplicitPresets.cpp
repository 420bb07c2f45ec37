#include "geometry/implicit/ImplicitPresets.hpp"

#include "geometry/implicit/Blob.hpp"
#include "geometry/implicit/Superellipsoid.hpp"

namespace dropscope {

std::shared_ptr<const ImplicitFunction> makeSuperellipsoid(const Eigen::Vector3d& semiAxes,
                                                           const Eigen::Vector2d& exponents) {
    return std::make_shared<const Superellipsoid>(semiAxes, exponents);
}

std::shared_ptr<const ImplicitFunction> makeBlob(const std::vector<Point>& centers, const std::vector<double>& radii,
                                                 double blend) {
    return std::make_shared<const Blob>(centers, radii, blend);
}

}  // namespace dropscope
