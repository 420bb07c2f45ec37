#pragma once

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"

#include <memory>
#include <numbers>
#include <random>

// Seeded random geometry for property tests. Each case builds its own Rng from its index, so a
// failing case is replayed by its index alone.
namespace dropscope::testing {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// The order in which a call's arguments are evaluated is the compiler's (GCC right to left, clang left to right):
// draws that feed one call are made one statement each, z first, so every compiler builds the cases GCC did.
inline Point randomPoint(Rng& rng, double halfWidth, const Point& center = Point::Zero()) {
    const double z = uniform(rng, -halfWidth, halfWidth);
    const double y = uniform(rng, -halfWidth, halfWidth);
    const double x = uniform(rng, -halfWidth, halfWidth);
    return center + Point(x, y, z);
}

// Uniform on the unit sphere.
inline Direction randomDirection(Rng& rng) {
    std::normal_distribution<double> normal;
    const double z = normal(rng);
    const double y = normal(rng);
    const double x = normal(rng);
    return Direction(x, y, z);
}

inline Eigen::Matrix3d randomRotation(Rng& rng) {
    const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    return rotationAboutAxis(randomDirection(rng), angle);
}

inline Sphere randomSphere(Rng& rng, const Point& around, double size) {
    const double radius = uniform(rng, 0.2, 1.0) * size;
    return Sphere(randomPoint(rng, size, around), radius);
}

inline Ellipsoid randomEllipsoid(Rng& rng, const Point& around, double size) {
    const double semiAxisZ = uniform(rng, 0.2, 1.0) * size;
    const double semiAxisY = uniform(rng, 0.2, 1.0) * size;
    const Eigen::Vector3d semiAxes(uniform(rng, 0.2, 1.0) * size, semiAxisY, semiAxisZ);
    const Eigen::Matrix3d rotation = randomRotation(rng);
    return Ellipsoid::fromSemiAxes(randomPoint(rng, size, around), semiAxes, rotation);
}

inline Box randomBox(Rng& rng, const Point& around, double size) {
    const Point lower = randomPoint(rng, size, around);
    const double edgeZ = uniform(rng, 0.2, 2.0) * size;
    const double edgeY = uniform(rng, 0.2, 2.0) * size;
    const Eigen::Vector3d edges(uniform(rng, 0.2, 2.0) * size, edgeY, edgeZ);
    return Box(lower, lower + edges);
}

// Case i of a mixed family: boxes, spheres and rotated ellipsoids in turn.
inline std::unique_ptr<Shape> randomShape(Rng& rng, int i, const Point& around, double size) {
    switch (i % 3) {
    case 0: return std::make_unique<Box>(randomBox(rng, around, size));
    case 1: return std::make_unique<Sphere>(randomSphere(rng, around, size));
    default: return std::make_unique<Ellipsoid>(randomEllipsoid(rng, around, size));
    }
}

inline Point boundsCenter(const Shape& s) { return s.bounds().center(); }

inline double boundsDiagonal(const Shape& s) { return s.bounds().diagonal().norm(); }

}  // namespace dropscope::testing
