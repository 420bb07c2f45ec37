#pragma once

#include "geometry/Shape.hpp"

namespace dropscope {

// Axis-aligned rectangular prism between a lower vertex p0 and an upper vertex p1 (seed 1.1).
class Box : public Shape {
public:
    // Throws std::invalid_argument unless p0 < p1 in every coordinate and both are finite.
    Box(const Point& lower, const Point& upper);

    const Point& lower() const { return lower_; }
    const Point& upper() const { return upper_; }
    Point center() const { return 0.5 * (lower_ + upper_); }
    Eigen::Vector3d edgeLengths() const { return upper_ - lower_; }

    ShapeKind kind() const override { return ShapeKind::Box; }
    std::string_view typeName() const override { return "box"; }

    double xMin() const override { return lower_.x(); }
    double xMax() const override { return upper_.x(); }
    double yMin() const override { return lower_.y(); }
    double yMax() const override { return upper_.y(); }
    double zMin() const override { return lower_.z(); }
    double zMax() const override { return upper_.z(); }

    double surfaceArea() const override;
    double volume() const override;
    PointLocation locatePoint(const Point& p) const override;
    using Shape::encloses;
    // Whether `other` lies completely inside this box, touching allowed (seed 1.1.9): a glass cell
    // holding droplets.
    bool encloses(const Shape& other) const;
    bool mayMeetBox(const Eigen::AlignedBox3d& box) const override { return bounds().intersects(box); }
    bool sameFormAs(const Shape& other) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    void print(std::ostream& os) const override;
    std::unique_ptr<Shape> clone() const override { return std::make_unique<Box>(*this); }
    double surfaceBand() const override { return band_; }

private:
    double exitDistance(const Point& p, const Direction& d) const;
    double entryDistance(const Point& p, const Direction& d) const;

    Point lower_;
    Point upper_;
    double band_;
};

}  // namespace dropscope
