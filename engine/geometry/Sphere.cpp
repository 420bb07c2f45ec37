#include "geometry/Sphere.hpp"

#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>

namespace dropscope {

Sphere::Sphere(const Point& center, double radius) : geometry_(SphereGeometry::make(center, radius)) {
    if (!center.allFinite()) throw std::invalid_argument("sphere centre must be finite");
    if (!std::isfinite(radius) || radius <= 0.0) throw std::invalid_argument("sphere radius must be finite and > 0");
}

double Sphere::surfaceArea() const { return 4.0 * std::numbers::pi * radius() * radius(); }

double Sphere::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius() * radius() * radius(); }

PointLocation Sphere::locatePoint(const Point& p) const { return geometry_.locate(p); }

double Sphere::distanceToSurface(const Point& p, const Direction& d) const { return geometry_.distanceToSurface(p, d); }

Direction Sphere::normal(const Point& p) const {
    if (!surfaceContains(p)) return Direction::invalid();
    return Direction(p - center());  // seed 1.2.8, normalised exactly rather than divided by R
}

bool Sphere::sameFormAs(const Shape& other) const {
    const auto* sphere = dynamic_cast<const Sphere*>(&other);
    return sphere && sphere->radius() == radius();
}

void Sphere::print(std::ostream& os) const {
    os << "Sphere(center=";
    printPoint(os, center()) << ", radius=" << radius() << ')';
}

}  // namespace dropscope
