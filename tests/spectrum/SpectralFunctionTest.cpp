#include "spectrum/SpectralFunction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dropscope {
namespace {

// Closed forms evaluated in a different order than the code: a few roundings of numbers ~1.
constexpr double kClosedForm = 1e-14;

template <typename Call>
std::string messageOf(Call call) {
    try {
        call();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "no error";
}

TEST(SpectralFunction, DefaultIsTheConstantOne) {
    const SpectralFunction one;
    EXPECT_TRUE(one.isConstant());
    EXPECT_EQ(one.at(500.0), 1.0);
    EXPECT_EQ(one.domainNm(), std::nullopt);
    EXPECT_EQ(SpectralFunction::constant(1.33).at(123.0), 1.33);
}

TEST(SpectralFunction, TableIsPiecewiseLinearOnItsRange) {
    const auto table = SpectralFunction::table({{400.0, 1.0}, {500.0, 2.0}, {650.0, 5.0}});
    EXPECT_EQ(table.kind(), SpectralFunction::Kind::Table);
    EXPECT_EQ(table.at(400.0), 1.0);
    EXPECT_EQ(table.at(500.0), 2.0);
    EXPECT_EQ(table.at(650.0), 5.0);
    EXPECT_NEAR(table.at(450.0), 1.5, kClosedForm);
    EXPECT_NEAR(table.at(600.0), 2.0 + 3.0 * 100.0 / 150.0, kClosedForm);
    EXPECT_EQ(table.domainNm(), (std::pair{400.0, 650.0}));
    EXPECT_EQ(messageOf([&] { table.at(700.0); }), "700 nm is outside the table (400-650 nm)");
    EXPECT_THROW(table.at(399.9), std::out_of_range);
}

TEST(SpectralFunction, CauchyIsAPolynomialInInverseSquaredMicrometres) {
    // n = A + B/lambda^2 + C/lambda^4 at 0.5 um: 1.5 + 0.004 * 4 + 0.0001 * 16
    const auto cauchy = SpectralFunction::cauchy({1.5, 0.004, 0.0001});
    EXPECT_NEAR(cauchy.at(500.0), 1.5 + 0.016 + 0.0016, kClosedForm);
    EXPECT_EQ(SpectralFunction::cauchy({1.45}).at(300.0), 1.45);
    EXPECT_EQ(cauchy.domainNm(), std::nullopt);
}

TEST(SpectralFunction, SellmeierGivesTheRootOfItsSum) {
    // One term, B = 1, C = 0.01 um^2, at 1 um: n^2 = 1 + 1/(1 - 0.01)
    const auto sellmeier = SpectralFunction::sellmeier({1.0}, {0.01});
    EXPECT_NEAR(sellmeier.at(1000.0), std::sqrt(1.0 + 1.0 / 0.99), kClosedForm);
    // Two terms, the first with C = 0 (a constant B), the second with its pole above: 1 + 1.25 + 1/(1 - 4)
    EXPECT_NEAR(SpectralFunction::sellmeier({1.25, 1.0}, {0.0, 4.0}).at(1000.0), std::sqrt(2.25 + 1.0 / (1.0 - 4.0)),
                kClosedForm);
}

TEST(SpectralFunction, SellmeierHasNoRealValueAtAPoleOrWhereTheSquareIsNegative) {
    // A pole at lambda^2 = C = 0.25 um^2, 500 nm
    const auto sellmeier = SpectralFunction::sellmeier({1.0}, {0.25});
    EXPECT_EQ(messageOf([&] { sellmeier.at(500.0); }), "the Sellmeier model has a pole at 500 nm");
    // Just below the pole the term is hugely negative: n^2 < 0
    EXPECT_THROW(sellmeier.at(499.0), std::domain_error);
}

TEST(SpectralFunction, RefusesWavelengthsThatAreNotPositive) {
    EXPECT_THROW(SpectralFunction::cauchy({1.5}).at(0.0), std::out_of_range);
    EXPECT_THROW(SpectralFunction::constant(1.0).at(-1.0), std::out_of_range);
    EXPECT_THROW(SpectralFunction::constant(1.0).at(std::numeric_limits<double>::quiet_NaN()), std::out_of_range);
}

TEST(SpectralFunction, FactoriesNameWhatIsWrong) {
    EXPECT_EQ(messageOf([] {
                  SpectralFunction::table({{650.0, 1.0}, {600.0, 2.0}});
              }),
              "table wavelengths must be strictly ascending (600 nm after 650 nm)");
    EXPECT_EQ(messageOf([] { SpectralFunction::table({{500.0, 1.0}}); }), "a table needs at least 2 points, not 1");
    EXPECT_EQ(messageOf([] { SpectralFunction::cauchy({}); }), "a Cauchy model needs at least one coefficient");
    EXPECT_EQ(messageOf([] {
                  SpectralFunction::sellmeier({1.0, 2.0, 3.0}, {1.0, 2.0});
              }),
              "Sellmeier B and C must have the same length (3 and 2)");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(SpectralFunction::table({{500.0, 1.0}, {500.0, 2.0}}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::table({{-1.0, 1.0}, {500.0, 2.0}}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::table({{400.0, nan}, {500.0, 2.0}}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::table({{400.0, 1.0}, {inf, 2.0}}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::constant(nan), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::cauchy({1.5, inf}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::sellmeier({}, {}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::sellmeier({1.0}, {nan}), std::invalid_argument);
    EXPECT_THROW(SpectralFunction::builtin(Material::Water, OpticalQuantity::N, nan), std::invalid_argument);
}

TEST(SpectralFunction, KeepsWhatTheSceneGave) {
    const auto sellmeier = SpectralFunction::sellmeier({1.0, 0.5}, {0.01, 100.0});
    EXPECT_EQ(sellmeier.coefficients(), (std::vector<double>{1.0, 0.5}));
    EXPECT_EQ(sellmeier.sellmeierC(), (std::vector<double>{0.01, 100.0}));
    const auto water = SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 35.0);
    EXPECT_EQ(water.material(), Material::Water);
    EXPECT_EQ(water.quantity(), OpticalQuantity::N);
    EXPECT_EQ(water.temperatureC(), 35.0);
    EXPECT_EQ(water, SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 35.0));
    EXPECT_NE(water, SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 36.0));
}

}  // namespace
}  // namespace dropscope
