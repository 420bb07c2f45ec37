#include "geometry/Sphere.hpp"

#include "geometry/RayQuadric.hpp"
#include "geometry/Tolerance.hpp"

#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>

namespace dropscope {

Sphere::Sphere(const Point& center, double radius)
    : center_(center), radius_(radius),
      band_(tolerance::surfaceBand(radius, center.cwiseAbs().maxCoeff())) {
    if (!center.allFinite()) throw std::invalid_argument("sphere centre must be finite");
    if (!std::isfinite(radius) || radius <= 0.0)
        throw std::invalid_argument("sphere radius must be finite and > 0");
}

double Sphere::surfaceArea() const { return 4.0 * std::numbers::pi * radius_ * radius_; }

double Sphere::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_; }

PointLocation Sphere::locatePoint(const Point& p) const {
    const double signedDistance = (p - center_).norm() - radius_;  // seed eq. 1.5
    if (std::isnan(signedDistance)) return PointLocation::Outside;
    if (std::abs(signedDistance) <= band_) return PointLocation::OnSurface;
    return signedDistance < 0.0 ? PointLocation::Inside : PointLocation::Outside;
}

double Sphere::distanceToSurface(const Point& p, const Direction& d) const {
    if (!d || !p.allFinite()) return std::nan("");
    // seed eqs. 1.10-1.12: s^2 + 2Bs + C = 0
    const Eigen::Vector3d offset = p - center_;
    const double b = offset.dot(d.vector());
    const double c = offset.squaredNorm() - radius_ * radius_;
    // B^2 - C = R^2 - |offset - B d|^2: the squared half-chord, free of the cancellation in B^2 - C.
    const double perpendicular = (offset - b * d.vector()).norm();
    const double discriminant = (radius_ - perpendicular) * (radius_ + perpendicular);
    return quadricDistance({1.0, b, c, discriminant}, locatePoint(p), band_);
}

Direction Sphere::normal(const Point& p) const {
    if (!surfaceContains(p)) return Direction::invalid();
    return Direction(p - center_);  // seed 1.2.8, normalised exactly rather than divided by R
}

void Sphere::print(std::ostream& os) const {
    os << "Sphere(center=";
    printPoint(os, center_) << ", radius=" << radius_ << ')';
}

}  // namespace dropscope
