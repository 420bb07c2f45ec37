#include "spectrum/Water.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "spectrum/SpectralFunction.hpp"

namespace dropscope {
namespace {

// The release's verification values are printed with 8 decimals: half a unit of the last one.
constexpr double kVerificationDigits = 5e-9;
// The built-in index uses Kell's density, which sits up to 0.004 kg/m^3 below IAPWS-95 between 0 and
// 25 C (kKellDensity below); dn/drho ~ 4.5e-4 per kg/m^3 at 226.5 nm, so 1.8e-6, plus half a unit of the
// release table's sixth decimal.
constexpr double kBuiltinAgainstIapwsTable = 2.5e-6;
// Kell's fit against IAPWS densities: his scale puts the maximum at 999.972 kg/m^3 where later absolute
// measurements give 999.975 (about 3 ppm); the IPTS-68 conversion is good to 0.002 K (0.0015 kg/m^3).
constexpr double kKellDensity = 0.005;
// n_D of water at 20 C relative to air, 1.33299, to the last printed digit (5e-6), the air index used to
// make it absolute (1e-6), and the formulation's own misfit in the visible, which Harvey et al. say exceeds
// the best liquid data's accuracy: a few 1e-5.
constexpr double kSodiumDAt20C = 3e-5;
// A density Kell prints with 3 decimals: half a unit of the last.
constexpr double kKellPrinted = 0.0005;

TEST(IapwsWaterIndex, ReproducesTheReleasesVerificationValues) {
    // IAPWS R9-97, the values printed for checking programs (T, rho given)
    EXPECT_NEAR(iapwsWaterIndex(997.047435, 298.15, 226.5), 1.39277824, kVerificationDigits);
    EXPECT_NEAR(iapwsWaterIndex(30.4758534, 773.15, 589.3), 1.00949307, kVerificationDigits);
}

TEST(IapwsWaterIndex, IsOneAtZeroDensity) {
    // (S5): the Lorentz-Lorenz function is proportional to the density
    EXPECT_EQ(iapwsWaterIndex(0.0, 300.0, 500.0), 1.0);
}

TEST(IapwsWaterIndex, FallsWithWavelengthAndTemperatureInTheVisible) {
    EXPECT_GT(iapwsWaterIndex(998.0, 293.15, 400.0), iapwsWaterIndex(998.0, 293.15, 700.0));
    EXPECT_GT(iapwsWaterIndex(998.0, 293.15, 589.3), iapwsWaterIndex(998.0, 313.15, 589.3));
}

TEST(WaterDensityAtOneBar, AgreesWithPublishedDensities) {
    // 0 C, 0.101325 MPa: IAPWS G12-15 (supercooled water), its check table
    EXPECT_NEAR(waterDensityAtOneBar(0.0), 999.84229, kKellDensity);
    // 25 C, 0.1 MPa: IAPWS SR6-08 (liquid water at 0.1 MPa), its check table
    EXPECT_NEAR(waterDensityAtOneBar(25.0), 997.047013, kKellDensity);
    // The normal boiling point, 373.1243 K = 99.974 C (ITS-90), saturated liquid: IAPWS SR1-86(1992)
    EXPECT_NEAR(waterDensityAtOneBar(99.9743), 958.365, kKellDensity);
}

TEST(WaterDensityAtOneBar, HasItsMaximumNearFourDegrees) {
    // Kell (1975): the maximum, 999.972 kg/m^3, at 3.98 C
    const double atMaximum = waterDensityAtOneBar(3.98);
    EXPECT_NEAR(atMaximum, 999.972, kKellPrinted);
    EXPECT_GT(atMaximum, waterDensityAtOneBar(3.5));
    EXPECT_GT(atMaximum, waterDensityAtOneBar(4.5));
}

TEST(BuiltinWater, MatchesTheIapwsTableAtZeroAndTwentyFiveDegrees) {
    // Release Table 3 at 273.15 K and 0.1 MPa: n = 1.394527 at 226.5 nm, 1.334344 at 589 nm, 1.326135 at
    // 1013.98 nm (its three wavelengths; the values as reproduced in public test suites of the release)
    const SpectralFunction atZero = SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 0.0);
    EXPECT_NEAR(atZero.at(226.5), 1.394527, kBuiltinAgainstIapwsTable);
    EXPECT_NEAR(atZero.at(589.0), 1.334344, kBuiltinAgainstIapwsTable);
    EXPECT_NEAR(atZero.at(1013.98), 1.326135, kBuiltinAgainstIapwsTable);
    // The verification point at 298.15 K is liquid water at atmospheric pressure
    EXPECT_NEAR(SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 25.0).at(226.5), 1.39277824,
                kBuiltinAgainstIapwsTable);
}

TEST(BuiltinWater, GivesTheSodiumDIndexAtTwentyDegrees) {
    // n_D = 1.33299 at 20 C relative to air (Tilton and Taylor 1938, as the CRC Handbook gives it), made
    // absolute with dry air's 1.000271 at 589 nm, 20 C, 101.325 kPa (Edlen)
    const double absolute = 1.33299 * 1.000271;
    EXPECT_NEAR(SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 20.0).at(589.3), absolute,
                kSodiumDAt20C);
}

TEST(BuiltinWater, RefusesTemperaturesOutsideItsRange) {
    EXPECT_NO_THROW(SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 100.0));
    try {
        SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 120.0);
        FAIL() << "no error";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "the built-in water index is offered from 0 to 100 degrees C, not 120");
    }
    EXPECT_THROW(SpectralFunction::builtin(Material::Water, OpticalQuantity::N, -0.5), std::invalid_argument);
}

TEST(BuiltinWater, IndexIsDefinedOnTheReleasesWavelengths) {
    const auto water = SpectralFunction::builtin(Material::Water, OpticalQuantity::N);
    EXPECT_EQ(water.domainNm(), kWaterIndexWavelengthRangeNm);
    EXPECT_NO_THROW(water.at(200.0));
    EXPECT_NO_THROW(water.at(1100.0));
    try {
        water.at(1200.0);
        FAIL() << "no error";
    } catch (const std::out_of_range& error) {
        EXPECT_STREQ(error.what(), "1200 nm is outside the built-in water n (200-1100 nm)");
    }
}

}  // namespace
}  // namespace dropscope
