#pragma once

#include "geometry/Shape.hpp"
#include "geometry/SphereGeometry.hpp"

namespace dropscope {

// Sphere of centre r0 and radius R (seed 1.2).
class Sphere : public Shape {
public:
    // Throws std::invalid_argument unless the centre is finite and the radius finite and > 0.
    Sphere(const Point& center, double radius);

    const Point& center() const { return geometry_.center; }
    double radius() const { return geometry_.radius; }
    const SphereGeometry& geometry() const { return geometry_; }

    ShapeKind kind() const override { return ShapeKind::Sphere; }
    std::string_view typeName() const override { return "sphere"; }

    double xMin() const override { return geometry_.center.x() - geometry_.radius; }
    double xMax() const override { return geometry_.center.x() + geometry_.radius; }
    double yMin() const override { return geometry_.center.y() - geometry_.radius; }
    double yMax() const override { return geometry_.center.y() + geometry_.radius; }
    double zMin() const override { return geometry_.center.z() - geometry_.radius; }
    double zMax() const override { return geometry_.center.z() + geometry_.radius; }

    double surfaceArea() const override;
    double volume() const override;
    PointLocation locatePoint(const Point& p) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    bool mayMeetBox(const Eigen::AlignedBox3d& box) const override {
        return box.squaredExteriorDistance(center()) <= radius() * radius();
    }
    bool sameFormAs(const Shape& other) const override;
    void print(std::ostream& os) const override;
    std::unique_ptr<Shape> clone() const override { return std::make_unique<Sphere>(*this); }
    double surfaceBand() const override { return geometry_.band; }

private:
    SphereGeometry geometry_;
};

}  // namespace dropscope
