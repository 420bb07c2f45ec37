#include "optics/Fresnel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

double squared(double x) { return x * x; }

TEST(Fresnel, NormalIncidence) {
    const double n1 = 1.0, n2 = 1.333;
    const FresnelReflectance r = fresnelReflectance(1.0, n1, n2);
    const double expected = squared((n1 - n2) / (n1 + n2));  // 0.02037...
    EXPECT_NEAR(r.s, expected, 1e-16);
    EXPECT_NEAR(r.p, expected, 1e-16);
    EXPECT_NEAR(fresnelReflectance(1.0, n2, n1).unpolarised(), expected, 1e-16);  // same from inside
    EXPECT_NEAR(schlickReflectance(1.0, n1, n2), expected, 1e-16);
}

TEST(Fresnel, BrewsterAngleExtinguishesP) {
    const double n1 = 1.0, n2 = 1.5;
    const double brewster = std::atan(n2 / n1);
    const FresnelReflectance r = fresnelReflectance(std::cos(brewster), n1, n2);
    EXPECT_NEAR(r.p, 0.0, 1e-15);
    EXPECT_GT(r.s, 0.1);
}

TEST(Fresnel, TotalBeyondTheCriticalAngle) {
    const double n1 = 1.5, n2 = 1.0;
    const double critical = std::asin(n2 / n1);
    EXPECT_EQ(fresnelReflectance(std::cos(critical + 1e-3), n1, n2).unpolarised(), 1.0);
    EXPECT_LT(fresnelReflectance(std::cos(critical - 1e-3), n1, n2).unpolarised(), 1.0);
    EXPECT_GT(fresnelReflectance(std::cos(critical - 1e-9), n1, n2).unpolarised(), 0.99);
    EXPECT_EQ(schlickReflectance(std::cos(critical + 1e-3), n1, n2), 1.0);
}

// At 45 degrees from air into n = 1.5: Rs = 0.0920, and Rp = Rs^2 exactly (an identity at 45 degrees).
TEST(Fresnel, ObliqueValues) {
    const FresnelReflectance r = fresnelReflectance(std::cos(std::numbers::pi / 4), 1.0, 1.5);
    const double cosT = std::sqrt(1.0 - 0.5 / 2.25);
    const double c = std::cos(std::numbers::pi / 4);
    EXPECT_NEAR(r.s, squared((c - 1.5 * cosT) / (c + 1.5 * cosT)), 1e-16);
    EXPECT_NEAR(r.s, 0.0920, 5e-5);
    EXPECT_NEAR(r.p, r.s * r.s, 1e-17);
}

// Energy: R + T = 1 per polarisation, with T from the Fresnel transmission amplitudes.
TEST(Fresnel, ReflectanceAndTransmittanceAddToOne) {
    for (double n2 : {1.2, 1.333, 1.5, 2.4}) {
        for (double cosI = 0.02; cosI <= 1.0; cosI += 0.02) {
            const double n1 = 1.0;
            const double cosT = std::sqrt(1.0 - squared(n1 / n2) * (1.0 - cosI * cosI));
            const double ts = 2 * n1 * cosI / (n1 * cosI + n2 * cosT);
            const double tp = 2 * n1 * cosI / (n2 * cosI + n1 * cosT);
            const double factor = n2 * cosT / (n1 * cosI);
            const FresnelReflectance r = fresnelReflectance(cosI, n1, n2);
            EXPECT_NEAR(r.s + factor * ts * ts, 1.0, 1e-14);
            EXPECT_NEAR(r.p + factor * tp * tp, 1.0, 1e-14);
        }
    }
}

TEST(Fresnel, SchlickIsCloseButNotExact) {
    const double exact = fresnelReflectance(std::cos(1.2), 1.0, 1.5).unpolarised();
    const double schlick = schlickReflectance(std::cos(1.2), 1.0, 1.5);
    EXPECT_NEAR(schlick, exact, 0.03);
    EXPECT_NE(schlick, exact);
}

}  // namespace
}  // namespace dropscope
