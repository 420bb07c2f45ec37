// Bad input is refused with a message fit for the user (the CLI prints it as it is).
#include "wave/Mie.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dropscope {
namespace {

std::string messageOf(const auto& call) {
    try {
        call();
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "(nothing thrown)";
}

TEST(MieInput, SizeParameterOutsideTheValidRange) {
    EXPECT_EQ(messageOf([] { mieCoefficients({1.33, 0.0}, 3e4); }), "size parameter x = 30000 is outside 1e-3..2e4");
    EXPECT_EQ(messageOf([] { mieCoefficients({1.33, 0.0}, 1e-4); }), "size parameter x = 1e-04 is outside 1e-3..2e4");
    EXPECT_THROW(mieCoefficients({1.33, 0.0}, std::nan("")), std::invalid_argument);
    EXPECT_NO_THROW(mieCoefficients({1.33, 0.0}, kMinSizeParameter));
    EXPECT_NO_THROW(mieCoefficients({1.33, 0.0}, kMaxSizeParameter));
}

TEST(MieInput, RefractiveIndex) {
    EXPECT_EQ(messageOf([] {
                  mieCoefficients({1.33, -0.1}, 1.0);
              }),
              "relative refractive index m = 1.33 + -0.1i must have a finite imaginary part >= 0 (absorption is + "
              "i kappa)");
    EXPECT_EQ(messageOf([] {
                  mieCoefficients({0.0, 1.0}, 1.0);
              }),
              "relative refractive index m = 0 + 1i must have a finite real part > 0");
    EXPECT_THROW(mieCoefficients({std::numeric_limits<double>::infinity(), 0.0}, 1.0), std::invalid_argument);
}

TEST(MieInput, AnglesAndRanges) {
    const MieCoefficients coefficients = mieCoefficients({1.33, 0.0}, 2.0);
    EXPECT_EQ(messageOf([&] { mieAmplitudes(coefficients, 1.5); }), "cos theta = 1.5 is outside -1..1");
    EXPECT_EQ(messageOf([] {
                  mieAverageOverSizeParameter({1.33, 0.0}, 5.0, 4.0, 3, 0);
              }),
              "size parameter range 5..4 is reversed");
    EXPECT_EQ(messageOf([] {
                  mieAverageOverSizeParameter({1.33, 0.0}, 1.0, 3e4, 3, 0);
              }),
              "highest size parameter x = 30000 is outside 1e-3..2e4");
    EXPECT_EQ(messageOf([] {
                  mieAverageOverSizeParameter({1.33, 0.0}, 1.0, 2.0, 0, 0);
              }),
              "an average over sizes needs at least one size");
    EXPECT_EQ(messageOf([] {
                  mieAverageOverRadii({1.33, 0.0}, RadiusDistribution::fixed(1.0), 3e4, 0);
              }),
              "radius 1 gives size parameter x = 30000, outside 1e-3..2e4");
    EXPECT_EQ(messageOf([] {
                  mieAverageOverRadii({1.33, 0.0}, RadiusDistribution::fixed(1.0), -1.0, 0);
              }),
              "wavenumber -1 must be finite and > 0");
}

}  // namespace
}  // namespace dropscope
