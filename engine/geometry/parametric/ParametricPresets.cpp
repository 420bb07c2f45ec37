#include "geometry/parametric/ParametricPresets.hpp"

#include "geometry/parametric/BezierSurface.hpp"
#include "geometry/parametric/EllipsoidSurface.hpp"
#include "geometry/parametric/TorusSurface.hpp"

#include <cmath>
#include <stdexcept>

namespace dropscope {

std::shared_ptr<const ParametricSurface> makeSphereSurface(double radius) {
    if (!(std::isfinite(radius) && radius > 0.0)) throw std::invalid_argument("radius must be finite and > 0");
    return std::make_shared<const EllipsoidSurface>(Eigen::Vector3d::Constant(radius),
                                                    EllipsoidSurface::Preset::Sphere);
}

std::shared_ptr<const ParametricSurface> makeEllipsoidSurface(const Eigen::Vector3d& semiAxes) {
    if (!(semiAxes.allFinite() && (semiAxes.array() > 0.0).all()))
        throw std::invalid_argument("semi_axes must be finite and > 0");
    return std::make_shared<const EllipsoidSurface>(semiAxes, EllipsoidSurface::Preset::Ellipsoid);
}

std::shared_ptr<const ParametricSurface> makeTorusSurface(double majorRadius, double minorRadius) {
    if (!std::isfinite(majorRadius)) throw std::invalid_argument("major_radius must be finite");
    if (!(minorRadius > 0.0 && minorRadius < majorRadius))
        throw std::invalid_argument("minor_radius must be > 0 and < major_radius");
    return std::make_shared<const TorusSurface>(majorRadius, minorRadius);
}

std::shared_ptr<const ParametricSurface> makeBezierSurface(const std::vector<std::vector<BezierNet>>& patches) {
    return std::make_shared<const BezierSurface>(patches);  // checks the net (BezierSurface.hpp)
}

}  // namespace dropscope
