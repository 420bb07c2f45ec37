#include "geometry/parametric/TorusSurface.hpp"

#include <cmath>
#include <numbers>

namespace dropscope {

TorusSurface::TorusSurface(double majorRadius, double minorRadius) : major_(majorRadius), minor_(minorRadius) {}

ParameterDomain TorusSurface::domain() const { return {0.0, 2.0 * std::numbers::pi, 0.0, 2.0 * std::numbers::pi}; }

Point TorusSurface::point(double u, double v) const {
    const double rho = major_ + minor_ * std::cos(v);  // distance from the z axis
    return {rho * std::cos(u), rho * std::sin(u), minor_ * std::sin(v)};
}

SurfaceJet TorusSurface::jet(double u, double v) const {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    const double rho = major_ + minor_ * cv;
    return {Point(rho * cu, rho * su, minor_ * sv), Eigen::Vector3d(-rho * su, rho * cu, 0.0),
            Eigen::Vector3d(-minor_ * sv * cu, -minor_ * sv * su, minor_ * cv)};
}

SurfaceHessians TorusSurface::hessians(double u, double v) const {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    const double rho = major_ + minor_ * cv;
    return {Eigen::Vector3d(-rho * cu, -rho * su, 0.0), Eigen::Vector3d(minor_ * sv * su, -minor_ * sv * cu, 0.0),
            Eigen::Vector3d(-minor_ * cv * cu, -minor_ * cv * su, -minor_ * sv)};
}

std::vector<PresetParameter> TorusSurface::presetParameters() const {
    return {{"major_radius", {}, {major_}}, {"minor_radius", {}, {minor_}}};
}

}  // namespace dropscope
