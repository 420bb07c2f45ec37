#include "geometry/Ellipsoid.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/SurfaceIntegrals.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <utility>

namespace dropscope {
namespace {

using testing::Rng;
using testing::uniform;

constexpr double kPi = std::numbers::pi;
constexpr double kFullAccuracy = 1e-10;

// The perimeter of an ellipse of semi-axes a, b: 4 a E(e), e^2 = 1 - b^2 / a^2 (a >= b), through the
// arithmetic-geometric mean (exact to rounding).
double ellipsePerimeter(double a, double b) {
    if (a < b) std::swap(a, b);
    double x = a, y = b, sum = 0.5 * (a * a + b * b), power = 0.5;
    while (std::abs(x - y) > 1e-16 * x) {
        const double c = 0.5 * (x - y);
        const double nx = 0.5 * (x + y), ny = std::sqrt(x * y);
        power *= 2.0;
        sum -= power * c * c;
        x = nx;
        y = ny;
    }
    return 2.0 * kPi * sum / x;
}

TEST(SurfaceIntegrals, EllipsoidAreaAndVolumeMatchClosedForms) {
    const Eigen::Vector3d cases[] = {{1.0, 1.0, 1.0}, {2.0, 1.0, 0.5}, {0.3, 0.3, 1.5},  {1.5, 1.5, 0.2},
                                     {3.0, 1.0, 0.3}, {0.7, 1.9, 1.1}, {1.0, 0.05, 1.0}, {10.0, 1.0, 1.0}};
    int index = 0;
    for (const Eigen::Vector3d& axes : cases) {
        const auto surface = makeEllipsoidSurface(axes);
        const QuadratureResult area = surfaceAreaIntegral(*surface, Eigen::Matrix3d::Identity(), kFullAccuracy);
        const double exactArea = ellipsoidSurfaceArea(axes);
        EXPECT_NEAR(area.value / exactArea, 1.0, kFullAccuracy) << "case " << index;
        EXPECT_LE(area.errorEstimate, 1.01 * kFullAccuracy * area.value) << "case " << index;
        EXPECT_DOUBLE_EQ(exactArea, Ellipsoid::fromSemiAxes(Point::Zero(), axes).surfaceArea());

        // seed 000 eq. 1.73; negative: the seed's parametrisation has r_u x r_v pointing inward.
        const QuadratureResult volume = signedVolumeIntegral(*surface, 1e-13);
        const double exactVolume = 4.0 / 3.0 * kPi * axes.prod();
        EXPECT_LT(volume.value, 0.0) << "case " << index;
        EXPECT_NEAR(-volume.value / exactVolume, 1.0, 1e-12) << "case " << index;
        ++index;
    }
}

TEST(SurfaceIntegrals, SphereAndTorus) {
    for (const double radius : {0.001, 1.0, 37.0}) {
        const auto sphere = makeSphereSurface(radius);
        const double area = surfaceAreaIntegral(*sphere, Eigen::Matrix3d::Identity(), kFullAccuracy).value;
        EXPECT_NEAR(area / (4.0 * kPi * radius * radius), 1.0, kFullAccuracy) << "radius " << radius;
    }
    for (const auto& [major, minor] : {std::pair{2.0, 0.5}, std::pair{1.0, 0.99}, std::pair{5.0, 0.01}}) {
        const auto torus = makeTorusSurface(major, minor);
        const QuadratureResult area = surfaceAreaIntegral(*torus, Eigen::Matrix3d::Identity(), kFullAccuracy);
        EXPECT_NEAR(area.value / (4.0 * kPi * kPi * major * minor), 1.0, kFullAccuracy) << major << ' ' << minor;
        const QuadratureResult volume = signedVolumeIntegral(*torus, 1e-13);
        EXPECT_GT(volume.value, 0.0);  // r_u x r_v points outward
        EXPECT_NEAR(volume.value / (2.0 * kPi * kPi * major * minor * minor), 1.0, 1e-12) << major << ' ' << minor;
    }
}

// seed 000 eq. 1.68: M maps the unit sphere onto the ellipsoid y^T (M M^T)^-1 y = 1.
TEST(SurfaceIntegrals, TransformedUnitSphereIsAnEllipsoid) {
    const auto sphere = makeSphereSurface(1.0);
    Rng rng(2024);
    for (int i = 0; i < 12; ++i) {
        const Eigen::Vector3d axes(uniform(rng, 0.2, 3.0), uniform(rng, 0.2, 3.0), uniform(rng, 0.2, 3.0));
        const Eigen::Matrix3d rotation = testing::randomRotation(rng);
        // diag(a, b, c) R: R maps the sphere onto itself, the scaling makes it the axis-aligned ellipsoid.
        const Eigen::Matrix3d scaled = axes.asDiagonal() * rotation;
        const double area = surfaceAreaIntegral(*sphere, scaled, kFullAccuracy).value;
        EXPECT_NEAR(area / ellipsoidSurfaceArea(axes), 1.0, kFullAccuracy) << "case " << i;
        // R diag(a, b, c) R^T with a reflection mixed in: the same ellipsoid, rotated.
        const Eigen::Matrix3d reflected = rotation * axes.asDiagonal() * Eigen::Vector3d(1, -1, 1).asDiagonal();
        EXPECT_NEAR(surfaceAreaIntegral(*sphere, reflected, kFullAccuracy).value / ellipsoidSurfaceArea(axes), 1.0,
                    kFullAccuracy)
            << "case " << i;

        // A shear (seed 000 A.6): ones on the diagonal, random off-diagonal factors.
        Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                if (r != c) shear(r, c) = uniform(rng, -0.8, 0.8);
        if (std::abs(shear.determinant()) < 0.05) continue;
        const Ellipsoid image = Ellipsoid::fromMatrix(Point::Zero(), (shear * shear.transpose()).inverse());
        const double sheared = surfaceAreaIntegral(*sphere, shear, kFullAccuracy).value;
        EXPECT_NEAR(sheared / image.surfaceArea(), 1.0, 1e-9) << "case " << i;
    }
}

TEST(SurfaceIntegrals, TransformedTorusScalesLikeItsArea) {
    const auto torus = makeTorusSurface(2.0, 0.7);
    const double base = 4.0 * kPi * kPi * 2.0 * 0.7;
    Rng rng(5);
    const Eigen::Matrix3d similarity = 1.7 * testing::randomRotation(rng);
    EXPECT_NEAR(surfaceAreaIntegral(*torus, similarity, kFullAccuracy).value / (1.7 * 1.7 * base), 1.0, kFullAccuracy);
    // Stretched by 1.5 along its axis the tube's cross-section becomes an ellipse of semi-axes r, 1.5 r
    // about the same centre circle: Pappus gives 2 pi R times that ellipse's perimeter.
    Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
    stretch(2, 2) = 1.5;
    const double stretched = surfaceAreaIntegral(*torus, stretch, kFullAccuracy).value;
    EXPECT_NEAR(stretched / (2.0 * kPi * 2.0 * ellipsePerimeter(0.7, 1.05)), 1.0, kFullAccuracy);
}

TEST(SurfaceIntegrals, FullAccuracyIsFast) {
    const auto ellipsoid = makeEllipsoidSurface(Eigen::Vector3d(2.0, 1.0, 0.4));
    const auto torus = makeTorusSurface(3.0, 1.0);
    const auto start = std::chrono::steady_clock::now();
    const QuadratureResult a = surfaceAreaIntegral(*ellipsoid, Eigen::Matrix3d::Identity(), kFullAccuracy);
    const auto middle = std::chrono::steady_clock::now();
    const QuadratureResult b = surfaceAreaIntegral(*torus, Eigen::Matrix3d::Identity(), kFullAccuracy);
    const auto end = std::chrono::steady_clock::now();
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::cout << "full-accuracy area: ellipsoid " << ms(middle - start) << " ms (error estimate "
              << a.errorEstimate / a.value << "), torus " << ms(end - middle) << " ms (error estimate "
              << b.errorEstimate / b.value << ")\n";
    EXPECT_NEAR(a.value / ellipsoidSurfaceArea(Eigen::Vector3d(2.0, 1.0, 0.4)), 1.0, kFullAccuracy);
}

}  // namespace
}  // namespace dropscope
