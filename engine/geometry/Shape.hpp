#pragma once

#include "geometry/Vector.hpp"

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string_view>

namespace dropscope {

// Parametric and Implicit are GeneralShapes (geometry/GeneralShape.hpp).
enum class ShapeKind { Box, Sphere, Ellipsoid, Parametric, Implicit };

// Where a point lies with respect to a shape's surface band (see tolerance::kSurfaceRelative).
// Every shape answers surfaceContains/encloses through this one classification, so the three
// answers can never disagree.
enum class PointLocation { Inside, OnSurface, Outside };

using MediumId = std::uint32_t;

// A closed volume in space: the interface of seed 000 chapter 1 / seed 001 "Shape".
class Shape {
public:
    virtual ~Shape() = default;

    virtual ShapeKind kind() const = 0;
    virtual std::string_view typeName() const = 0;

    // Extreme points in each Cartesian coordinate (seed 1.1.1, 1.2.1, 1.3.1).
    virtual double xMin() const = 0;
    virtual double xMax() const = 0;
    virtual double yMin() const = 0;
    virtual double yMax() const = 0;
    virtual double zMin() const = 0;
    virtual double zMax() const = 0;
    // The axis-aligned box between those extremes.
    Eigen::AlignedBox3d bounds() const;

    virtual double surfaceArea() const = 0;
    virtual double volume() const = 0;

    virtual PointLocation locatePoint(const Point& p) const = 0;
    // Strictly on the surface (within the surface band).
    bool surfaceContains(const Point& p) const { return locatePoint(p) == PointLocation::OnSurface; }
    // Strictly inside: not on the surface band and not outside.
    bool encloses(const Point& p) const { return locatePoint(p) == PointLocation::Inside; }
    // Positive volume of intersection; touching (within the surface bands) is not overlapping.
    bool overlaps(const Shape& other) const;
    // Whether the closed body may meet the closed `box`, without surface bands: exact for boxes, spheres
    // and ellipsoids, conservative (never false when they meet) for parametric and implicit shapes.
    virtual bool mayMeetBox(const Eigen::AlignedBox3d& box) const = 0;
    // Whether `other` is this shape moved: the same type and form (size, orientation, preset), wherever
    // it is placed. The medium is not compared.
    virtual bool sameFormAs(const Shape& other) const = 0;

    // The seed's distance semantics (seed 000 ch. 1 item 7; docs/geometry.md):
    //  inside          -> the positive root;
    //  on the surface  -> 0 when the ray leaves (or is tangent), the distance to the far side when it enters;
    //  outside         -> NaN when the ray never enters (misses, or only touches), else the nearest root.
    // A NaN (invalid) direction gives NaN.
    virtual double distanceToSurface(const Point& p, const Direction& d) const = 0;

    // Outward unit normal at a surface point; invalid Direction when p is not on the surface or the
    // normal is undefined there (box edges and vertices).
    virtual Direction normal(const Point& p) const = 0;

    virtual void print(std::ostream& os) const = 0;

    // A copy of the same dynamic type (medium included).
    virtual std::unique_ptr<Shape> clone() const = 0;

    // Half-width of this shape's surface band, in length units.
    virtual double surfaceBand() const = 0;

    MediumId mediumId() const { return mediumId_; }
    void setMediumId(MediumId id) { mediumId_ = id; }

protected:
    Shape() = default;
    Shape(const Shape&) = default;
    Shape& operator=(const Shape&) = default;

private:
    MediumId mediumId_ = 0;
};

std::ostream& operator<<(std::ostream& os, const Shape& shape);

}  // namespace dropscope
