#pragma once

#include "geometry/Shape.hpp"

namespace dropscope {

// Sphere of centre r0 and radius R (seed 1.2).
class Sphere : public Shape {
public:
    // Throws std::invalid_argument unless the centre is finite and the radius finite and > 0.
    Sphere(const Point& center, double radius);

    const Point& center() const { return center_; }
    double radius() const { return radius_; }

    ShapeKind kind() const override { return ShapeKind::Sphere; }
    std::string_view typeName() const override { return "sphere"; }

    double xMin() const override { return center_.x() - radius_; }
    double xMax() const override { return center_.x() + radius_; }
    double yMin() const override { return center_.y() - radius_; }
    double yMax() const override { return center_.y() + radius_; }
    double zMin() const override { return center_.z() - radius_; }
    double zMax() const override { return center_.z() + radius_; }

    double surfaceArea() const override;
    double volume() const override;
    PointLocation locatePoint(const Point& p) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    void print(std::ostream& os) const override;
    double surfaceBand() const override { return band_; }

private:
    Point center_;
    double radius_;
    double band_;
};

}  // namespace dropscope
