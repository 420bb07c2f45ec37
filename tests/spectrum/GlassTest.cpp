#include <gtest/gtest.h>

#include <stdexcept>

#include "spectrum/SpectralFunction.hpp"

namespace dropscope {
namespace {

// Schott prints n_d, n_F, n_C with 5 decimals (half a unit: 5e-6), and its Sellmeier fit does not
// reproduce its own catalogue exactly; we allow the same again for the fit.
constexpr double kCatalogueFiveDecimals = 1e-5;
// A 4-decimal textbook value: half a unit of its last digit.
constexpr double kFourDecimals = 5e-5;
// The catalogue's Abbe number has 2 decimals: half a unit, plus as much for the indices' own rounding.
constexpr double kAbbeTwoDecimals = 0.01;

// The Fraunhofer lines (nm) the catalogue uses: helium d, hydrogen F and C.
constexpr double kLineD = 587.5618;
constexpr double kLineF = 486.1327;
constexpr double kLineC = 656.2725;

TEST(Bk7, GivesTheSchottCatalogueIndices) {
    const auto bk7 = SpectralFunction::builtin(Material::Bk7, OpticalQuantity::N);
    EXPECT_NEAR(bk7.at(kLineD), 1.51680, kCatalogueFiveDecimals);
    EXPECT_NEAR(bk7.at(kLineF), 1.52238, kCatalogueFiveDecimals);
    EXPECT_NEAR(bk7.at(kLineC), 1.51432, kCatalogueFiveDecimals);
    // Abbe number v_d = (n_d - 1)/(n_F - n_C) = 64.17 in the catalogue
    EXPECT_NEAR((bk7.at(kLineD) - 1.0) / (bk7.at(kLineF) - bk7.at(kLineC)), 64.17, kAbbeTwoDecimals);
}

TEST(FusedSilica, GivesMalitsonsIndex) {
    const auto silica = SpectralFunction::builtin(Material::FusedSilica, OpticalQuantity::N);
    EXPECT_NEAR(silica.at(kLineD), 1.4585, kFourDecimals);
}

TEST(Glasses, AreDefinedOnTheirSourcesRanges) {
    const auto bk7 = SpectralFunction::builtin(Material::Bk7, OpticalQuantity::N);
    EXPECT_EQ(bk7.domainNm(), (std::pair{300.0, 2500.0}));
    EXPECT_THROW(bk7.at(290.0), std::out_of_range);
    const auto silica = SpectralFunction::builtin(Material::FusedSilica, OpticalQuantity::N);
    EXPECT_EQ(silica.domainNm(), (std::pair{210.0, 3710.0}));
    try {
        silica.at(4000.0);
        FAIL() << "no error";
    } catch (const std::out_of_range& error) {
        EXPECT_STREQ(error.what(), "4000 nm is outside the built-in fused_silica n (210-3710 nm)");
    }
}

TEST(Materials, AreNamedAsSceneFilesNameThem) {
    for (const Material material : {Material::Water, Material::Bk7, Material::FusedSilica}) {
        EXPECT_EQ(materialNamed(materialName(material)), material);
    }
    EXPECT_EQ(materialName(Material::FusedSilica), "fused_silica");
    EXPECT_EQ(materialNamed("BK7"), std::nullopt);
    EXPECT_EQ(materialNamed("glass"), std::nullopt);
}

}  // namespace
}  // namespace dropscope
