// Fraunhofer diffraction by a disk and an ellipse: the encircled energy against Born & Wolf's figures and an
// independent quadrature, its inverse, and the directions drawn from the Airy pattern against the closed form.
#include "optics/Diffraction.hpp"
#include "optics/Polarisation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

namespace dropscope {
namespace {

// 2 J1(t)^2 / t integrated by Simpson's rule on 20000 steps: an independent route to the encircled energy.
double encircledEnergyByQuadrature(double u) {
    constexpr int kSteps = 20000;
    const double h = u / kSteps;
    const auto density = [](double t) {
        if (t == 0.0) return 0.0;
        const double j1 = std::cyl_bessel_j(1.0, t);
        return 2.0 * j1 * j1 / t;
    };
    double sum = density(0.0) + density(u);
    for (int i = 1; i < kSteps; ++i) sum += (i % 2 ? 4.0 : 2.0) * density(i * h);
    return sum * h / 3.0;
}

TEST(AiryPattern, EncircledEnergyAtTheDarkRingsIsBornAndWolfs) {
    // Born & Wolf, Principles of Optics, 8.5.2: 83.8 %, 91.0 % and 93.8 % of the light fall within the first,
    // second and third dark rings (u = 3.832, 7.016, 10.173), given to three digits.
    EXPECT_NEAR(airyEncircledEnergy(3.8317), 0.838, 5e-4);
    EXPECT_NEAR(airyEncircledEnergy(7.0156), 0.910, 5e-4);
    EXPECT_NEAR(airyEncircledEnergy(10.1735), 0.938, 5e-4);
}

TEST(AiryPattern, EncircledEnergyIsTheIntegralOfItsDensity) {
    for (double u : {1e-4, 5e-4, 0.3, 2.0, 3.8317, 12.0, 55.0}) {
        EXPECT_NEAR(airyEncircledEnergy(u), encircledEnergyByQuadrature(u), 1e-10) << u;
    }
    // Far out, 1 - F ~ 2 / (pi u): the tail that carries the energy of wide angles.
    EXPECT_NEAR((1.0 - airyEncircledEnergy(5000.0)) * std::numbers::pi * 5000.0 / 2.0, 1.0, 1e-3);
}

// The quantile inverts a cubic Hermite table of F (step 0.02) up to u = 500, and F itself beyond: within 1e-9 in p
// there (Diffraction.cpp's bound on the interpolant), to rounding beyond.
constexpr double kTableInverseError = 1e-9;

TEST(AiryPattern, QuantileInvertsTheEncircledEnergy) {
    double worst = 0.0;
    for (int k = 1; k < 20000; ++k) {
        const double p = 0.9987 * k / 20000.0;
        const double error = std::abs(airyEncircledEnergy(airyRadiusQuantile(p)) - p);
        worst = std::max(worst, error);
    }
    EXPECT_LT(worst, kTableInverseError);
    std::cout << "[airy] largest |F(quantile(p)) - p| over 20000 p below 0.9987: " << worst << "\n";
    for (double p : {1e-12, 1e-6, 0.01, 0.3, 0.5, 0.838, 0.9, 0.99}) {
        EXPECT_NEAR(airyEncircledEnergy(airyRadiusQuantile(p)), p, kTableInverseError) << p;
    }
    for (double p : {0.9988, 0.999, 0.99999, 0.9999999}) {
        EXPECT_NEAR(airyEncircledEnergy(airyRadiusQuantile(p)), p, 1e-14) << p;
    }
    EXPECT_EQ(airyRadiusQuantile(0.0), 0.0);
    EXPECT_THROW(airyRadiusQuantile(1.0), std::invalid_argument);
    EXPECT_THROW(airyRadiusQuantile(-0.1), std::invalid_argument);
}

// Kolmogorov-Smirnov distance between the samples and the encircled energy truncated at uMax.
double ksDistance(std::vector<double> u, double uMax) {
    std::sort(u.begin(), u.end());
    const double kept = airyEncircledEnergy(uMax);
    double worst = 0.0;
    const auto n = static_cast<double>(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
        const double model = airyEncircledEnergy(u[i]) / kept;
        worst = std::max({worst, std::abs(model - static_cast<double>(i) / n),
                          std::abs(model - (static_cast<double>(i) + 1.0) / n)});
    }
    return worst;
}

// 1.63 / sqrt(n): the Kolmogorov-Smirnov distance a correct sampler exceeds with probability 1 %.
double ksLimit(std::size_t n) { return 1.63 / std::sqrt(static_cast<double>(n)); }

TEST(AiryPattern, DiskDirectionsFollowTheAiryPattern) {
    const Direction along(0.0, 0.0, 1.0);
    const ProjectedEllipse disk{2.0, 2.0, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    const double wavenumber = 30.0;  // ka = 60
    std::mt19937_64 engine(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> u;
    double sumCos = 0.0;
    double sumSin = 0.0;
    constexpr std::size_t kSamples = 40000;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const Direction d = diffractedDirection(along, disk, wavenumber, [&] { return uniform(engine); });
        ASSERT_TRUE(d);
        const double sine = std::hypot(d.x(), d.y());
        u.push_back(wavenumber * disk.a * sine);
        if (sine > 0.0) {
            sumCos += d.x() / sine;
            sumSin += d.y() / sine;
        }
    }
    EXPECT_LT(ksDistance(u, wavenumber * disk.a), ksLimit(kSamples));
    // Isotropic about the axis: the mean azimuth vector vanishes to its noise (1/sqrt(2n) per component).
    EXPECT_LT(std::abs(sumCos) / kSamples, 5.0 / std::sqrt(2.0 * kSamples));
    EXPECT_LT(std::abs(sumSin) / kSamples, 5.0 / std::sqrt(2.0 * kSamples));
}

TEST(AiryPattern, EllipseDirectionsAreTheDisksStretchedAcrossItsAxes) {
    // An ellipse's far field is the disk's with u = k sqrt((a q1)^2 + (b q2)^2): twice as narrow along the long
    // axis a = 2 b. Its scaled radius follows the disk's law, and |q1| is half |q2| in distribution.
    const Direction along(0.0, 0.0, 1.0);
    const ProjectedEllipse ellipse{3.0, 1.5, Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX()};
    const double wavenumber = 40.0;
    std::mt19937_64 engine(11);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> scaled;
    std::vector<double> q1;
    std::vector<double> q2;
    constexpr std::size_t kSamples = 40000;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const Direction d = diffractedDirection(along, ellipse, wavenumber, [&] { return uniform(engine); });
        const double s1 = d.dot(ellipse.e1);
        const double s2 = d.dot(ellipse.e2);
        scaled.push_back(wavenumber * std::hypot(ellipse.a * s1, ellipse.b * s2));
        q1.push_back(std::abs(s1));
        q2.push_back(std::abs(s2));
    }
    // The truncation sin(theta) <= 1 cuts only where u > k b = 60, beyond 99.4 % of the energy: the KS test on
    // u <= 60 is the untruncated law's restricted to there.
    std::vector<double> inner;
    for (double value : scaled) {
        if (value <= wavenumber * ellipse.b) inner.push_back(value);
    }
    EXPECT_LT(ksDistance(inner, wavenumber * ellipse.b), ksLimit(inner.size()));
    std::nth_element(q1.begin(), q1.begin() + kSamples / 2, q1.end());
    std::nth_element(q2.begin(), q2.begin() + kSamples / 2, q2.end());
    EXPECT_NEAR(q1[kSamples / 2] / q2[kSamples / 2], 0.5, 0.02);
}

TEST(AiryPattern, SmallDropletsStillGiveDirectionsWithinTheForwardHemisphere) {
    // ka = 0.5: most of the Airy pattern lies beyond sin(theta) = 1 and is cut; what is drawn is forward.
    const Direction along(0.0, 0.6, 0.8);
    const ProjectedEllipse disk{1.0, 1.0, Eigen::Vector3d::UnitX(), Eigen::Vector3d(0.0, 0.8, -0.6)};
    std::mt19937_64 engine(3);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const Direction d = diffractedDirection(along, disk, 0.5, [&] { return uniform(engine); });
        ASSERT_TRUE(d);
        EXPECT_GE(d.dot(along.vector()), 0.0);
    }
}

TEST(TurnedReference, FollowsTheTurnAndStaysPerpendicular) {
    const Direction from(0.0, 0.0, 1.0);
    const Direction to(std::sin(0.3), 0.0, std::cos(0.3));
    // A reference in the plane of the turn turns with it; one across it is unchanged.
    const Eigen::Vector3d inPlane = turnedReference(Eigen::Vector3d::UnitX(), from, to);
    EXPECT_NEAR((inPlane - Eigen::Vector3d(std::cos(0.3), 0.0, -std::sin(0.3))).norm(), 0.0, 1e-15);
    const Eigen::Vector3d across = turnedReference(Eigen::Vector3d::UnitY(), from, to);
    EXPECT_NEAR((across - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-15);
    const Eigen::Vector3d oblique = turnedReference(Eigen::Vector3d(1.0, 1.0, 0.0).normalized(), from, to);
    EXPECT_NEAR(oblique.norm(), 1.0, 1e-15);
    EXPECT_NEAR(oblique.dot(to.vector()), 0.0, 1e-15);
}

}  // namespace
}  // namespace dropscope
