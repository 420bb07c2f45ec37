#include "geometry/parametric/EllipsoidSurface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope {

namespace {

// s = sqrt(1 - u^2) and its derivatives s' = -u / s, s'' = -1 / s^3; (1 - u)(1 + u) keeps s accurate
// near the poles. At a pole (s = 0) s' and s'' are unbounded: 0 stands for them (their finite part).
struct Profile {
    double s;
    double ds;
    double dds;
};

Profile profile(double u) {
    const double s = std::sqrt(std::max(0.0, (1.0 - u) * (1.0 + u)));
    if (s == 0.0) return {0.0, 0.0, 0.0};
    return {s, -u / s, -1.0 / (s * s * s)};
}

}  // namespace

EllipsoidSurface::EllipsoidSurface(const Eigen::Vector3d& semiAxes, Preset preset)
    : semiAxes_(semiAxes), preset_(preset) {}

ParameterDomain EllipsoidSurface::domain() const { return {-1.0, 1.0, 0.0, 2.0 * std::numbers::pi}; }

Point EllipsoidSurface::point(double u, double v) const {
    const double s = profile(u).s;
    return {semiAxes_.x() * s * std::cos(v), semiAxes_.y() * s * std::sin(v), semiAxes_.z() * u};
}

SurfaceJet EllipsoidSurface::jet(double u, double v) const {
    const Profile p = profile(u);
    const double a = semiAxes_.x(), b = semiAxes_.y(), c = semiAxes_.z();
    const double cv = std::cos(v), sv = std::sin(v);
    return {Point(a * p.s * cv, b * p.s * sv, c * u), Eigen::Vector3d(a * p.ds * cv, b * p.ds * sv, c),
            Eigen::Vector3d(-a * p.s * sv, b * p.s * cv, 0.0)};
}

SurfaceHessians EllipsoidSurface::hessians(double u, double v) const {
    const Profile p = profile(u);
    const double a = semiAxes_.x(), b = semiAxes_.y();
    const double cv = std::cos(v), sv = std::sin(v);
    return {Eigen::Vector3d(a * p.dds * cv, b * p.dds * sv, 0.0), Eigen::Vector3d(-a * p.ds * sv, b * p.ds * cv, 0.0),
            Eigen::Vector3d(-a * p.s * cv, -b * p.s * sv, 0.0)};
}

double EllipsoidSurface::characteristicLength() const { return 2.0 * semiAxes_.maxCoeff(); }

std::string_view EllipsoidSurface::presetName() const { return preset_ == Preset::Sphere ? "sphere" : "ellipsoid"; }

std::vector<PresetParameter> EllipsoidSurface::presetParameters() const {
    if (preset_ == Preset::Sphere) return {{"radius", {}, {semiAxes_.x()}}};
    return {{"semi_axes", {3}, {semiAxes_.x(), semiAxes_.y(), semiAxes_.z()}}};
}

}  // namespace dropscope
