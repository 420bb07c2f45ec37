#include "geometry/Ellipsoid.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

constexpr double kPi = std::numbers::pi;

// Seed eq. 1.33: 8abc times a double integral over one octant.
double seedOctantIntegral(double a, double b, double c) {
    using Quadrature = boost::math::quadrature::gauss_kronrod<double, 61>;
    auto inner = [&](double v) {
        auto integrand = [&](double u) {
            const double w = 1.0 - u * u;
            return std::sqrt(w * std::cos(v) * std::cos(v) / (a * a) + w * std::sin(v) * std::sin(v) / (b * b) +
                             u * u / (c * c));
        };
        return Quadrature::integrate(integrand, 0.0, 1.0, 10, 1e-14);
    };
    return 8.0 * a * b * c * Quadrature::integrate(inner, 0.0, kPi / 2, 10, 1e-14);
}

// Seed eq. 1.30 (Legendre form), valid for a >= b >= c with a > c.
double seedLegendreForm(double a, double b, double c) {
    const double delta = 1.0 - c * c / (a * a);    // eq. 1.31
    const double epsilon = 1.0 - c * c / (b * b);  // eq. 1.32
    const double phi = std::asin(std::sqrt(delta));
    const double k = std::sqrt(epsilon / delta);
    const double f = boost::math::ellint_1(k, phi);
    const double e = boost::math::ellint_2(k, phi);
    return 2 * kPi * c * c + 2 * kPi * a * b / std::sqrt(delta) * ((1 - delta) * f + delta * e);
}

TEST(EllipsoidSurfaceArea, SphereIsFourPiRSquared) {
    for (double r : {1e-6, 0.3, 1.0, 42.0}) {
        EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(r, r, r)), 4 * kPi * r * r, 1e-14 * 4 * kPi * r * r);
    }
}

TEST(EllipsoidSurfaceArea, ProlateSpheroidClosedForm) {
    const double a = 1.0, c = 2.5;
    const double e = std::sqrt(1.0 - a * a / (c * c));
    const double expected = 2 * kPi * a * a * (1.0 + c / (a * e) * std::asin(e));
    EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(a, a, c)), expected, 1e-13 * expected);
    EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(c, a, a)), expected, 1e-13 * expected);
}

TEST(EllipsoidSurfaceArea, OblateSpheroidClosedForm) {
    const double a = 2.0, c = 0.5;
    const double e = std::sqrt(1.0 - c * c / (a * a));
    const double expected = 2 * kPi * a * a * (1.0 + (1.0 - e * e) / e * std::atanh(e));
    EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(a, a, c)), expected, 1e-13 * expected);
    EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(a, c, a)), expected, 1e-13 * expected);
}

TEST(EllipsoidSurfaceArea, NearlySphericalIsContinuous) {
    const double r = 1.0;
    const double area = ellipsoidSurfaceArea(Eigen::Vector3d(r * (1 + 1e-9), r, r * (1 - 1e-9)));
    EXPECT_NEAR(area, 4 * kPi, 1e-8);
}

TEST(EllipsoidSurfaceArea, MatchesSeedIntegralAndLegendreForm) {
    const double cases[][3] = {{3.0, 2.0, 1.0}, {1.5, 1.0, 0.5}, {10.0, 1.0, 0.1}, {1.01, 1.0, 0.99}, {5.0, 4.9, 0.2}};
    for (const auto& axes : cases) {
        const double a = axes[0], b = axes[1], c = axes[2];
        SCOPED_TRACE(::testing::Message() << a << ", " << b << ", " << c);
        const double carlson = ellipsoidSurfaceArea(Eigen::Vector3d(a, b, c));
        EXPECT_NEAR(carlson, seedLegendreForm(a, b, c), 1e-12 * carlson);
        EXPECT_NEAR(carlson, seedOctantIntegral(a, b, c), 1e-9 * carlson);
        // symmetric in the order of the axes
        EXPECT_NEAR(ellipsoidSurfaceArea(Eigen::Vector3d(c, a, b)), carlson, 1e-14 * carlson);
    }
}

}  // namespace
}  // namespace dropscope
