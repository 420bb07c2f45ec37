#pragma once

// Shapes and random placements shared by the ParametricShape tests (distance, locate, shape, Bezier shape).
#include "geometry/RandomGeometry.hpp"
#include "geometry/parametric/ParametricBase.hpp"
#include "geometry/parametric/ParametricPresets.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <memory>

namespace dropscope::testing {

// The preset bases, built once per test binary: the unit sphere, the torus R = 2, r = 0.5, and the
// ellipsoid with semi-axes (1, 0.5, 0.3).
inline const std::shared_ptr<const ParametricBase>& sphereBase() {
    static const auto base = makeParametricBase(makeSphereSurface(1.0));
    return base;
}

inline const std::shared_ptr<const ParametricBase>& torusBase() {
    static const auto base = makeParametricBase(makeTorusSurface(2.0, 0.5));
    return base;
}

inline const std::shared_ptr<const ParametricBase>& ellipsoidBase() {
    static const auto base = makeParametricBase(makeEllipsoidSurface({1.0, 0.5, 0.3}));
    return base;
}

// What randomMatrix draws. The seeded cases of each test were chosen with its own draws, so a test keeps
// the variant it was written with: changing one changes every case after it.
struct RandomMatrixDraws {
    bool shearXZ = true;               // draw the (0, 2) shear term too (after (0, 1) and (1, 2))
    Eigen::Index reflectedColumn = 0;  // the column negated when reflecting
};

// Rotation, anisotropic scaling (0.5 to 2 per axis), shear (off-diagonal terms up to 0.4) and, when
// `reflect`, a reflection: a non-similar map with well-separated singular values.
inline Eigen::Matrix3d randomMatrix(Rng& rng, bool reflect, RandomMatrixDraws draws = {}) {
    Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
    shear(0, 1) = uniform(rng, -0.4, 0.4);
    shear(1, 2) = uniform(rng, -0.4, 0.4);
    if (draws.shearXZ) shear(0, 2) = uniform(rng, -0.4, 0.4);
    const double scaleZ = uniform(rng, 0.5, 2.0);  // one draw a statement (RandomGeometry.hpp)
    const double scaleY = uniform(rng, 0.5, 2.0);
    const Eigen::Vector3d scale(uniform(rng, 0.5, 2.0), scaleY, scaleZ);
    Eigen::Matrix3d m = randomRotation(rng) * scale.asDiagonal() * shear;
    if (reflect) m.col(draws.reflectedColumn) *= -1.0;
    return m;
}

// Both NaN, or both finite and within `tol` of each other. Both within `tol` of 0 also agree: from a surface
// point, a ray within ~1e-6 rad of tangency leaves (0) or crosses a chord of ~1e-6 of the size, and which one is
// decided by the last bits of the two different representations of the surface.
inline ::testing::AssertionResult sameDistance(double actual, double expected, double tol) {
    if (std::isnan(actual) && std::isnan(expected)) return ::testing::AssertionSuccess();
    if (std::abs(actual) <= 100.0 * tol && std::abs(expected) <= 100.0 * tol) return ::testing::AssertionSuccess();
    if (std::isnan(actual) != std::isnan(expected) || !(std::abs(actual - expected) <= tol))
        return ::testing::AssertionFailure() << "parametric " << actual << " vs reference " << expected;
    return ::testing::AssertionSuccess();
}

}  // namespace dropscope::testing
