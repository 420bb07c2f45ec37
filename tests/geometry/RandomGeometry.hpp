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

inline Point randomPoint(Rng& rng, double halfWidth, const Point& center = Point::Zero()) {
    return center + Point(uniform(rng, -halfWidth, halfWidth), uniform(rng, -halfWidth, halfWidth),
                          uniform(rng, -halfWidth, halfWidth));
}

// Uniform on the unit sphere.
inline Direction randomDirection(Rng& rng) {
    std::normal_distribution<double> normal;
    return Direction(normal(rng), normal(rng), normal(rng));
}

inline Eigen::Matrix3d randomRotation(Rng& rng) {
    return rotationAboutAxis(randomDirection(rng), uniform(rng, 0.0, 2.0 * std::numbers::pi));
}

inline Sphere randomSphere(Rng& rng, const Point& around, double size) {
    return Sphere(randomPoint(rng, size, around), uniform(rng, 0.2, 1.0) * size);
}

inline Ellipsoid randomEllipsoid(Rng& rng, const Point& around, double size) {
    const Eigen::Vector3d semiAxes(uniform(rng, 0.2, 1.0) * size, uniform(rng, 0.2, 1.0) * size,
                                   uniform(rng, 0.2, 1.0) * size);
    return Ellipsoid::fromSemiAxes(randomPoint(rng, size, around), semiAxes, randomRotation(rng));
}

inline Box randomBox(Rng& rng, const Point& around, double size) {
    const Point lower = randomPoint(rng, size, around);
    const Eigen::Vector3d edges(uniform(rng, 0.2, 2.0) * size, uniform(rng, 0.2, 2.0) * size,
                                uniform(rng, 0.2, 2.0) * size);
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
