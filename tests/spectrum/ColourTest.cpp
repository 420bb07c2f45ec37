#include "spectrum/Colour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace dropscope {
namespace {

// Arithmetic on a handful of doubles of order 1: a few rounding errors of 1.1e-16.
constexpr double kRounding = 1e-15;
// The sums of the published 1 nm table at 360-830 nm (X 106.865469, Y 106.856917, Z 106.892251): the CIE
// normalised the three functions to equal integrals, which the 1931 table's rounding and the 1 nm
// interpolation keep to 3.3e-4 relatively; an error in a row of the table (a digit wrong) would not.
constexpr double kEqualIntegralsRelative = 4e-4;
// Hence the equal-energy spectrum's chromaticity is 1/3 to 1/3 of that, 1.3e-4 (measured: 1.9e-5, 4.6e-5).
constexpr double kEqualEnergyChromaticity = 1.5e-4;
// The 5 nm rows' sums quoted in the table's header (computed from another copy of the data): 16 digits of
// 95 additions of numbers below 2.
constexpr double kFiveNmSum = 1e-12;
// IEC 61966-2-1 prints its XYZ -> RGB matrix to 4 decimals, as the inverse of the 4-decimal RGB -> XYZ
// matrix rather than of the exact one: its entries differ from the exact inverse by up to 3.7e-4.
constexpr double kPrintedMatrix = 4e-4;
// The CIE's D65 tristimulus values (0.95047, 1, 1.08883), from the tabulated D65 spectrum, have the
// chromaticity (0.312727, 0.329023); sRGB's white is (0.3127, 0.3290) rounded: Z differs by 2.3e-4, B by 2.4e-4.
constexpr double kCieD65AsSrgbWhite = 3e-4;
// The sRGB curve's published constants (0.0031308, 12.92, 1.055, 2.4) are rounded: its two pieces meet to
// 2.9e-8, a ten-thousandth of one 8-bit step.
constexpr double kCurveJoin = 1e-7;
// Display colours compared with values computed by hand (4 digits) from the table row and the matrix.
constexpr double kHandComputed = 1e-3;

TEST(Colour, TableReadsBackThePublishedValues) {
    EXPECT_EQ(cieTableRangeNm(), (std::pair<double, double>{360, 830}));
    const Xyz at555 = cieColourMatching(555);
    EXPECT_EQ(at555.x, 0.5120501);
    EXPECT_EQ(at555.y, 1.0);
    EXPECT_EQ(at555.z, 0.005749999);
    const Xyz at600 = cieColourMatching(600);
    EXPECT_EQ(at600.x, 1.0622);
    EXPECT_EQ(at600.y, 0.631);
    EXPECT_EQ(at600.z, 0.0008);
    const Xyz at360 = cieColourMatching(360);
    EXPECT_EQ(at360.x, 0.0001299);
    EXPECT_EQ(at360.y, 0.000003917);
    EXPECT_EQ(at360.z, 0.0006061);
    const Xyz at830 = cieColourMatching(830);
    EXPECT_EQ(at830.x, 0.000001251141);
    EXPECT_EQ(at830.y, 0.00000045181);
    EXPECT_EQ(at830.z, 0.0);
}

TEST(Colour, InterpolatesLinearlyAndIsZeroOutside) {
    // Halfway between the 600 and 601 nm rows (1.0607352, 0.6181555, 0.00076096).
    const Xyz between = cieColourMatching(600.5);
    EXPECT_NEAR(between.x, 0.5 * (1.0622 + 1.0607352), kRounding);
    EXPECT_NEAR(between.y, 0.5 * (0.631 + 0.6181555), kRounding);
    EXPECT_NEAR(between.z, 0.5 * (0.0008 + 0.00076096), kRounding);
    for (double outside : {359.999, 830.001, 0.0, -1.0, 2000.0, std::nan("")}) {
        const Xyz none = cieColourMatching(outside);
        EXPECT_EQ(none.x, 0.0) << outside;
        EXPECT_EQ(none.y, 0.0) << outside;
        EXPECT_EQ(none.z, 0.0) << outside;
    }
}

TEST(Colour, EqualEnergyLightIsTheCieWhite) {
    Xyz sum;
    Xyz fiveNm;
    for (int nm = 360; nm <= 830; ++nm) {
        const Xyz m = cieColourMatching(nm);
        sum.x += m.x;
        sum.y += m.y;
        sum.z += m.z;
        if (nm % 5 == 0) {
            fiveNm.x += m.x;
            fiveNm.y += m.y;
            fiveNm.z += m.z;
        }
    }
    EXPECT_NEAR(fiveNm.x, 21.373139988621006, kFiveNmSum);
    EXPECT_NEAR(fiveNm.y, 21.371407850470007, kFiveNmSum);
    EXPECT_NEAR(fiveNm.z, 21.378664308989997, kFiveNmSum);
    EXPECT_NEAR(sum.x / sum.y, 1.0, kEqualIntegralsRelative);
    EXPECT_NEAR(sum.z / sum.y, 1.0, kEqualIntegralsRelative);
    const double total = sum.x + sum.y + sum.z;
    EXPECT_NEAR(sum.x / total, 1.0 / 3.0, kEqualEnergyChromaticity);
    EXPECT_NEAR(sum.y / total, 1.0 / 3.0, kEqualEnergyChromaticity);
    // The same through xyzOfLines: 471 lines of equal power.
    std::vector<std::pair<double, double>> lines;
    for (int nm = 360; nm <= 830; ++nm) lines.emplace_back(nm, 2.0);
    const Xyz viaLines = xyzOfLines(lines);
    EXPECT_NEAR(viaLines.y, 2.0 * sum.y, 1e-12);
    // Displayed: not sRGB's white (D65, 6504 K) but the warmer equal-energy white (5455 K). XYZ (1, 1, 1) is,
    // by hand with the matrix, linear (1.2050, 0.9483, 0.9086), scaled (1, 0.7870, 0.7541), encoded
    // (1, 0.8998, 0.8829): near white, red highest, blue lowest, the channels within 0.12.
    const Rgb shown = displaySrgbFromXyz(sum);
    EXPECT_NEAR(shown[0], 1.0, kRounding);
    EXPECT_NEAR(shown[1], 0.8998, kHandComputed);
    EXPECT_NEAR(shown[2], 0.8829, kHandComputed);
}

TEST(Colour, SrgbMatrixIsTheIecDefinition) {
    // sRGB's white, the chromaticity (0.3127, 0.3290) at Y = 1, is linear (1, 1, 1).
    const Rgb white = linearSrgbFromXyz({0.3127 / 0.3290, 1.0, (1.0 - 0.3127 - 0.3290) / 0.3290});
    for (double component : white) EXPECT_NEAR(component, 1.0, kRounding);
    const Rgb cieD65 = linearSrgbFromXyz({0.95047, 1.0, 1.08883});
    for (double component : cieD65) EXPECT_NEAR(component, 1.0, kCieD65AsSrgbWhite);
    // The columns against IEC 61966-2-1's printed XYZ -> RGB matrix.
    const double printed[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    const Xyz units[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int column = 0; column < 3; ++column) {
        const Rgb rgb = linearSrgbFromXyz(units[column]);
        for (int row = 0; row < 3; ++row) EXPECT_NEAR(rgb[row], printed[row][column], kPrintedMatrix);
    }
    // And the red primary (0.64, 0.33) is pure red.
    const Rgb red = linearSrgbFromXyz({0.64 / 0.33, 1.0, 0.03 / 0.33});
    EXPECT_NEAR(red[1] / red[0], 0.0, kRounding);
    EXPECT_NEAR(red[2] / red[0], 0.0, kRounding);
}

TEST(Colour, SrgbCurve) {
    EXPECT_EQ(srgbEncode(0.0), 0.0);
    EXPECT_NEAR(srgbEncode(1.0), 1.0, kRounding);
    EXPECT_NEAR(srgbEncode(0.5), 0.7353569830524495, kRounding);  // 1.055 * 0.5^(1/2.4) - 0.055
    EXPECT_NEAR(srgbEncode(0.001), 0.01292, kRounding);           // the linear piece, 12.92 x
    const double boundary = 0.0031308;
    EXPECT_NEAR(srgbEncode(boundary), 12.92 * boundary, kRounding);
    EXPECT_NEAR(srgbEncode(std::nextafter(boundary, 1.0)), 12.92 * boundary, kCurveJoin);
    EXPECT_EQ(srgbEncode(-0.5), 0.0);  // clamped to [0, 1]
    EXPECT_NEAR(srgbEncode(2.0), 1.0, kRounding);
    double previous = 0.0;
    for (int i = 1; i <= 10000; ++i) {
        const double next = srgbEncode(i / 10000.0);
        ASSERT_GT(next, previous) << i;
        previous = next;
    }
}

TEST(Colour, BlackStaysBlack) {
    EXPECT_EQ(displaySrgbFromXyz({0, 0, 0}), (Rgb{0, 0, 0}));
    EXPECT_EQ(displaySrgbFromXyz({-1, -1, -1}), (Rgb{0, 0, 0}));
    EXPECT_EQ(displaySrgbFromXyz({0.1, 0, 0.1}), (Rgb{0, 0, 0}));
    // Any brightness of a colour shows the same.
    EXPECT_EQ(displaySrgbFromXyz({1e-9, 2e-9, 1e-9}), displaySrgbFromXyz({1e9, 2e9, 1e9}));
}

// Spectral colours lie outside the sRGB gamut; adding white brings them in. Values by hand from the row
// and the matrix; the hue expected of each named in words.
TEST(Colour, SpectralColoursHaveTheirHues) {
    // A line's negative linear components are dropped (the hue of the gamut's edge nearest it), then the largest
    // is scaled to 1 and encoded. 610 nm: linear (2.4759, -0.0281, -0.0465): sRGB's red primary, whose dominant
    // wavelength is about 611 nm, so (1, 0, 0); 650 nm the same (no pink: docs/spectra.md, "Path colours").
    const auto expectColour = [](double nm, const Rgb& expected) {
        const Rgb shown = displayColourOfWavelength(nm);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(shown[k], expected[k], kRounding) << nm << " nm, component " << k;
    };
    expectColour(610, {1.0, 0.0, 0.0});
    expectColour(650, {1.0, 0.0, 0.0});
    // 600 nm orange: row (1.0622, 0.631, 0.0008) -> linear (2.4718, 0.1545, -0.0687) -> G 0.0625 of R,
    // encoded 0.277; 580 nm amber: (0.9163, 0.87, 0.00165) -> (1.6312, 0.7442, -0.1247) -> 0.4562, encoded 0.706.
    EXPECT_NEAR(displayColourOfWavelength(600)[1], 0.277, kHandComputed);
    EXPECT_EQ(displayColourOfWavelength(600)[2], 0.0);
    EXPECT_NEAR(displayColourOfWavelength(580)[1], 0.706, kHandComputed);
    // 470 nm: blue with a little green: linear (-0.1487, 0.0348, 1.3533) -> G 0.0257 of B, encoded (0, 0.175, 1).
    const Rgb at470 = displayColourOfWavelength(470);
    EXPECT_EQ(at470[0], 0.0);
    EXPECT_NEAR(at470[1], 0.175, kHandComputed);
    EXPECT_NEAR(at470[2], 1.0, kRounding);
    // 530 nm: linear (-0.8099, 1.4584, -0.1221): pure green.
    expectColour(530, {0.0, 1.0, 0.0});
    // Every displayed colour is in [0, 1] with its largest component 1.
    for (double nm = 360; nm <= 830; nm += 0.5) {
        const Rgb c = displayColourOfWavelength(nm);
        for (double component : c) {
            EXPECT_GE(component, 0.0) << nm;
            EXPECT_LE(component, 1.0) << nm;
        }
        EXPECT_NEAR(std::max({c[0], c[1], c[2]}), 1.0, kRounding) << nm;
    }
}

TEST(Colour, OutsideTheTableIsDimGrey) {
    const double grey = srgbEncode(0.3);
    for (double nm : {359.0, 200.0, 831.0, 1500.0}) {
        EXPECT_EQ(displayColourOfWavelength(nm), (Rgb{grey, grey, grey})) << nm;
    }
    EXPECT_NE(displayColourOfWavelength(830.0), (Rgb{grey, grey, grey}));
}

}  // namespace
}  // namespace dropscope
