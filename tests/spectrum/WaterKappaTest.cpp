#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "spectrum/SpectralFunction.hpp"

namespace dropscope {
namespace {

// Relative: a tabulated value read back goes through pow(y1/y0, 0) or pow(.., 1), exact or one rounding.
constexpr double kReadBack = 1e-14;

const SpectralFunction& kappa() {
    static const SpectralFunction water = SpectralFunction::builtin(Material::Water, OpticalQuantity::Kappa);
    return water;
}

TEST(WaterKappa, ReadsBackHaleAndQuerrysValues) {
    // Hale and Querry (1973), 25 C
    const std::pair<double, double> published[] = {{200.0, 1.10e-7}, {475.0, 9.35e-10}, {550.0, 1.96e-9},
                                                   {700.0, 3.35e-8}, {1000.0, 2.89e-6}, {2000.0, 1.10e-3}};
    for (const auto& [nm, k] : published) EXPECT_NEAR(kappa().at(nm), k, kReadBack * k) << nm << " nm";
}

TEST(WaterKappa, InterpolatesGeometricallyAndMonotonicallyBetweenRows) {
    // Halfway between 650 nm (1.64e-8) and 675 nm (2.23e-8) in log kappa: the geometric mean, (S8)
    EXPECT_NEAR(kappa().at(662.5), std::sqrt(1.64e-8 * 2.23e-8), kReadBack * 2e-8);
    double previous = kappa().at(650.0);
    for (double nm = 651.0; nm <= 675.0; nm += 1.0) {
        const double value = kappa().at(nm);
        EXPECT_GT(value, previous) << nm << " nm";
        previous = value;
    }
}

TEST(WaterKappa, IsDefinedOnTheTableOnly) {
    EXPECT_EQ(kappa().domainNm(), (std::pair{200.0, 2600.0}));
    try {
        kappa().at(190.0);
        FAIL() << "no error";
    } catch (const std::out_of_range& error) {
        EXPECT_STREQ(error.what(), "190 nm is outside the built-in water kappa (200-2600 nm)");
    }
    EXPECT_THROW(kappa().at(2700.0), std::out_of_range);
}

TEST(WaterKappa, OnlyWaterHasABuiltinKappaAndNothingABuiltinSigma) {
    try {
        SpectralFunction::builtin(Material::Bk7, OpticalQuantity::Kappa);
        FAIL() << "no error";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "no built-in kappa for bk7");
    }
    EXPECT_THROW(SpectralFunction::builtin(Material::FusedSilica, OpticalQuantity::Kappa), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::builtin(Material::Water, OpticalQuantity::Sigma), std::invalid_argument);
}

}  // namespace
}  // namespace dropscope
