#pragma once

#include "geometry/implicit/ImplicitFunction.hpp"

#include <Eigen/Core>

namespace dropscope {

// Barr's superellipsoid with semi-axes a, b, c and exponents e1 (north-south) and e2 (east-west),
// written as the gauge (Minkowski functional) of the body,
//   F(r) = psi^(e1/2),  psi = (|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1),  f = F - 1,
// homogeneous of degree 1, so |grad f| stays bounded. e1 = e2 = 1 is exactly the ellipsoid
// sqrt((x/a)^2 + (y/b)^2 + (z/c)^2) - 1. Preset "superellipsoid" {semi_axes [a, b, c], exponents [e1, e2]}.
class Superellipsoid final : public ImplicitFunction {
public:
    // Throws std::invalid_argument unless the semi-axes are finite and > 0 and both exponents lie in
    // [tolerance::implicit::kMinExponent, kMaxExponent] (ImplicitTolerance.hpp says why).
    Superellipsoid(const Eigen::Vector3d& semiAxes, const Eigen::Vector2d& exponents);

    const Eigen::Vector3d& semiAxes() const { return semiAxes_; }
    const Eigen::Vector2d& exponents() const { return exponents_; }

    // F(r): 1 on the surface.
    double gauge(const Eigen::Vector3d& r) const;

    double value(const Point& r) const override { return gauge(r) - 1.0; }
    Eigen::Vector3d gradient(const Point& r) const override;
    double lipschitzBound() const override { return lipschitz_; }
    double lipschitzAlong(const Eigen::Vector3d& direction) const override { return gauge(direction); }
    Eigen::AlignedBox3d bounds() const override { return {-semiAxes_, semiAxes_}; }
    // F is a norm (see Superellipsoid.cpp), hence convex; the centre is where it vanishes.
    std::optional<Point> convexCenter() const override { return Point::Zero(); }
    double characteristicLength() const override { return semiAxes_.minCoeff(); }
    std::string_view presetName() const override { return "superellipsoid"; }
    std::vector<PresetParameter> presetParameters() const override;

private:
    Eigen::Vector3d semiAxes_;
    Eigen::Vector2d exponents_;
    double p_;  // 2 / e2: the east-west power
    double q_;  // 2 / e1: the north-south power
    double lipschitz_;
};

}  // namespace dropscope
