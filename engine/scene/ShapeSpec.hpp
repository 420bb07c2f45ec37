#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/Shape.hpp"

#include <Eigen/Core>

#include <memory>

namespace dropscope {

class Ellipsoid;

// A plain, editable description of one shape: the fields the GUI shows and the scene writer writes.
// Only the fields of `kind` matter:
//   sphere:    center, radius;
//   ellipsoid: center, semiAxes (half-lengths along x, y, z before the rotation), and a right-handed
//              turn of rotationAngleDeg degrees about rotationAxis (any non-zero length);
//   box:       boxMin, boxMax (axis-aligned). describeShape sets center to the box's centre too, for
//              display; makeShape ignores it (withCenter moves a box);
//   parametric, implicit: general (the shape: its shared base, transform and form) and center, its
//              translation r0; makeShape places `general` at `center`, so moving one edits only r0.
struct ShapeSpec {
    ShapeKind kind = ShapeKind::Sphere;
    Point center = Point::Zero();
    double radius = 1.0;
    Eigen::Vector3d semiAxes{1.0, 1.0, 1.0};
    Eigen::Vector3d rotationAxis{0.0, 0.0, 1.0};
    double rotationAngleDeg = 0.0;
    Point boxMin{-1.0, -1.0, -1.0};
    Point boxMax{1.0, 1.0, 1.0};
    std::shared_ptr<const GeneralShape> general;
    MediumId medium = 0;
};

// The shape a spec describes, with its medium id set. Throws std::invalid_argument with a one-line
// message ("radius must be > 0", "box max must be > min on every axis (y: max 1 <= min 1)") when a
// number is not finite, a radius or semi-axis is <= 0, the rotation axis is zero, or boxMin >= boxMax
// on some axis.
std::unique_ptr<Shape> makeShape(const ShapeSpec& spec);

// The inverse of makeShape: makeShape(describeShape(s)) is s (exactly for spheres and boxes; for an
// ellipsoid the same matrix up to rounding, ~1e-15 relative). An ellipsoid is described in the frame of
// its axes closest to the identity (see ellipsoidFrame), so one read from a file without a rotation
// comes back with angle 0 and its semi-axes in x, y, z order.
ShapeSpec describeShape(const Shape& shape);

// `spec` moved so that its centre is `center` (a box keeps its edge lengths: boxMin and boxMax move).
ShapeSpec withCenter(ShapeSpec spec, const Point& center);

// A rotation as a right-handed turn of angleDeg in [0, 180] degrees about a unit axis.
struct AxisAngle {
    Eigen::Vector3d axis{0.0, 0.0, 1.0};
    double angleDeg = 0.0;
};

// The axis and angle of a proper rotation (orthonormal, det +1), through its quaternion (stable near 0
// and 180 degrees); the identity gives axis (0, 0, 1), angle 0. Inverse of rotationAboutAxis
// (geometry/Rotation.hpp) up to rounding.
AxisAngle axisAngleOf(const Eigen::Matrix3d& rotation);

// An ellipsoid's semi-axes and their directions as a proper rotation R (det +1), so that
// M = R diag(1/a^2, 1/b^2, 1/c^2) R^T with semiAxes = (a, b, c). Of the equivalent choices (the axes in
// any order, each with either sign) it takes the rotation closest to the identity (largest trace), so an
// unrotated ellipsoid gives R = I.
struct EllipsoidFrame {
    Eigen::Vector3d semiAxes;
    Eigen::Matrix3d rotation;
};
EllipsoidFrame ellipsoidFrame(const Ellipsoid& ellipsoid);

}  // namespace dropscope
