#include "ImplicitTestSupport.hpp"

#include "geometry/implicit/Superellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dropscope::testing {
namespace {

// (|s|^k + |t|^k)^(1/k), k = infinity allowed.
double pNorm(double s, double t, double k) {
    if (std::isinf(k)) return std::max(std::abs(s), std::abs(t));
    return std::pow(std::pow(std::abs(s), k) + std::pow(std::abs(t), k), 1.0 / k);
}

// The support function max ell . r over the superellipsoid: the dual norm of the gauge, nested with the
// conjugate exponents p* = p / (p - 1).
double support(const Eigen::Vector3d& s, const Eigen::Vector2d& e, const Eigen::Vector3d& ell) {
    const double p = 2.0 / e[1];
    const double q = 2.0 / e[0];
    const double pDual = p == 1.0 ? std::numeric_limits<double>::infinity() : p / (p - 1.0);
    const double qDual = q == 1.0 ? std::numeric_limits<double>::infinity() : q / (q - 1.0);
    return pNorm(pNorm(s.x() * ell.x(), s.y() * ell.y(), pDual), s.z() * ell.z(), qDual);
}

TEST(Superellipsoid, ClosedFormVolumeCheck) {
    // The formula itself: e1 = e2 = 1 is the ellipsoid.
    const Eigen::Vector3d s(1.0, 2.0, 3.0);
    EXPECT_NEAR(superellipsoidVolume(s, Eigen::Vector2d(1.0, 1.0)), 4.0 / 3.0 * std::numbers::pi * 6.0, 1e-12);
    // e1 = e2 = 2 is the octahedron, 4/3 abc.
    EXPECT_NEAR(superellipsoidVolume(s, Eigen::Vector2d(2.0, 2.0)), 4.0 / 3.0 * 6.0, 1e-12);
}

TEST(Superellipsoid, VolumeMatchesTheClosedFormWithinItsErrorEstimate) {
    const Eigen::Vector3d semiAxes(1.0, 0.7, 0.5);
    // 0.1 and 2 are the ends of the allowed range; 0.3 once took seconds (grazing integration lines).
    const Eigen::Vector2d cases[] = {{1.0, 1.0}, {0.2, 0.2}, {0.5, 1.5}, {1.8, 0.3}, {2.0, 1.0},
                                     {0.1, 0.1}, {0.3, 0.3}, {2.0, 2.0}, {0.1, 2.0}};
    for (const Eigen::Vector2d& e : cases) {
        const ImplicitShape shape(makeImplicitBase(makeSuperellipsoid(semiAxes, e)), AffineTransform());
        const IntegralEstimate volume = shape.volumeEstimate();
        const double exact = superellipsoidVolume(semiAxes, e);
        EXPECT_LE(std::abs(volume.value - exact), volume.errorEstimate) << "exponents " << e.transpose();
        EXPECT_LE(volume.errorEstimate, 1e-4 * exact) << "exponents " << e.transpose();
        std::printf("exponents %.1f %.1f: volume error %.2g, estimate %.2g (relative)\n", e[0], e[1],
                    std::abs(volume.value - exact) / exact, volume.errorEstimate / exact);
    }
}

TEST(Superellipsoid, ExtremesBracketTheSupportFunction) {
    const Eigen::Vector3d semiAxes(1.0, 0.7, 0.5);
    const Eigen::Vector2d cases[] = {{0.2, 0.2}, {0.5, 1.5}, {1.8, 0.3}};
    Rng rng(11);
    for (const Eigen::Vector2d& e : cases) {
        const auto base = makeImplicitBase(makeSuperellipsoid(semiAxes, e));
        const ImplicitShape shape(base, randomPlacement(rng));
        const Eigen::Matrix3d& m = shape.transform().matrix();
        const double tol = tolerance::implicit::kExtremeRelative * 1.0001 *
                           shape.transform().applyToBox(base->bounds()).diagonal().norm();
        const double actual[6] = {shape.xMin(), shape.xMax(), shape.yMin(), shape.yMax(), shape.zMin(), shape.zMax()};
        for (int k = 0; k < 3; ++k) {
            const double h = support(semiAxes, e, m.row(k).transpose());  // symmetric body: min = -max
            const double r0 = shape.transform().translation()[k];
            EXPECT_GE(r0 - h - actual[2 * k], -1e-12) << e.transpose() << " axis " << k;
            EXPECT_LE(r0 - h - actual[2 * k], tol) << e.transpose() << " axis " << k;
            EXPECT_GE(actual[2 * k + 1] - (r0 + h), -1e-12) << e.transpose() << " axis " << k;
            EXPECT_LE(actual[2 * k + 1] - (r0 + h), tol) << e.transpose() << " axis " << k;
        }
    }
}

TEST(Superellipsoid, GradientMatchesFiniteDifferencesAndLipschitzBoundHolds) {
    Rng rng(5);
    const Eigen::Vector3d semiAxes(1.0, 0.6, 0.3);
    for (const Eigen::Vector2d& e : {Eigen::Vector2d(0.3, 1.7), Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(1.9, 0.4)}) {
        const Superellipsoid f(semiAxes, e);
        for (int i = 0; i < 200; ++i) {
            const Point r = randomPoint(rng, 1.5);
            const Point s = randomPoint(rng, 1.5);
            ASSERT_LE(std::abs(f.value(r) - f.value(s)), f.lipschitzBound() * (r - s).norm() * (1 + 1e-12)) << i;
            ASSERT_LE(std::abs(f.value(r) - f.value(s)), f.lipschitzAlong(r - s) * (1 + 1e-12)) << i;
            const double h = 1e-6;
            Eigen::Vector3d numeric;
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(k);
                numeric[k] = (f.value(r + step) - f.value(r - step)) / (2 * h);
            }
            ASSERT_LT((f.gradient(r) - numeric).norm(), 1e-5 * (1.0 + numeric.norm())) << "case " << i;
        }
        // Far away and tiny coordinates: no overflow or NaN.
        EXPECT_NEAR(f.value(Point(1e300, 0, 0)), 1e300, 1e290);
        EXPECT_TRUE(f.gradient(Point(1e-300, 2e-300, -1e-300)).allFinite());
        EXPECT_TRUE(f.gradient(Point(0, 0, 0)).allFinite());
    }
}

TEST(Superellipsoid, BadParametersAreRejectedWithTheReason) {
    const Eigen::Vector3d ok(1, 1, 1);
    expectMessage([&] { makeSuperellipsoid(Eigen::Vector3d(1, 0, 1), Eigen::Vector2d(1, 1)); }, "semi_axes");
    expectMessage([&] { makeSuperellipsoid(Eigen::Vector3d(1, NAN, 1), Eigen::Vector2d(1, 1)); }, "semi_axes");
    expectMessage([&] { makeSuperellipsoid(ok, Eigen::Vector2d(2.5, 1)); }, "no Lipschitz bound");
    expectMessage([&] { makeSuperellipsoid(ok, Eigen::Vector2d(1, 0.05)); }, "exponents must be >= 0.1");
    expectMessage([&] { makeSuperellipsoid(ok, Eigen::Vector2d(1, -1)); }, "exponents");
    expectMessage([&] { makeSuperellipsoid(ok, Eigen::Vector2d(INFINITY, 1)); }, "exponents must be finite");
    expectMessage([&] { makeImplicitBase(nullptr); }, "null");
}

TEST(Superellipsoid, PrintsOneLineWithPresetAndPlacement) {
    const auto base = makeImplicitBase(makeSuperellipsoid(Eigen::Vector3d(1, 2, 3), Eigen::Vector2d(0.5, 1)));
    const ImplicitShape shape(base, AffineTransform::translation(Eigen::Vector3d(4, 5, 6)));
    std::ostringstream os;
    shape.print(os);
    EXPECT_EQ(os.str(),
              "implicit superellipsoid {semi_axes: [1, 2, 3], exponents: [0.5, 1]} "
              "M=[[1, 0, 0], [0, 1, 0], [0, 0, 1]] r0=(4, 5, 6)");
    EXPECT_EQ(shape.kind(), ShapeKind::Implicit);
    EXPECT_EQ(shape.typeName(), "implicit");
}

}  // namespace
}  // namespace dropscope::testing
