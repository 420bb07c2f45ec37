// Averages over sizes: weighted as docs/mie.md says (checked by hand with two sizes), equal to one sphere
// when there is one size, and independent of the thread count.
#include "wave/Mie.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

namespace dropscope {
namespace {

const std::complex<double> kWater{1.33, 1e-3};

void expectIdentical(const MieResult& a, const MieResult& b) {
    EXPECT_EQ(a.efficiencies.qext, b.efficiencies.qext);
    EXPECT_EQ(a.efficiencies.qsca, b.efficiencies.qsca);
    EXPECT_EQ(a.efficiencies.qabs, b.efficiencies.qabs);
    EXPECT_EQ(a.efficiencies.qback, b.efficiencies.qback);
    EXPECT_EQ(a.efficiencies.g, b.efficiencies.g);
    EXPECT_EQ(a.bins.fraction, b.bins.fraction);
    EXPECT_EQ(a.bins.s12, b.bins.s12);
    EXPECT_EQ(a.bins.s33, b.bins.s33);
    EXPECT_EQ(a.bins.s34, b.bins.s34);
    EXPECT_EQ(a.xMean, b.xMean);
    EXPECT_EQ(a.sizes, b.sizes);
}

TEST(MieAverage, FixedRadiusIsOneSphere) {
    const double wavenumber = 2.0 * 3.141592653589793 / 0.55;  // radii and wavelength in micrometres
    const MieResult cloud = mieAverageOverRadii(kWater, RadiusDistribution::fixed(3.0), wavenumber, 36);
    expectIdentical(cloud, mieSphere(kWater, wavenumber * 3.0, 36));
    expectIdentical(mieAverageOverSizeParameter(kWater, 12.5, 12.5, 1, 36), mieSphere(kWater, 12.5, 36));
}

// Over +-1e-4 about x = 20 the midpoint average departs from the middle sphere by ~(1e-4)^2 Q'' / 6,
// with |Q''| of order 10 away from a sharp resonance: 1e-7 of the values.
constexpr double kNarrowRangeTolerance = 1e-7;

TEST(MieAverage, NarrowRangeIsTheMiddleSphere) {
    const MieResult range = mieAverageOverSizeParameter(kWater, 20.0 - 1e-4, 20.0 + 1e-4, 5, 18);
    const MieResult middle = mieSphere(kWater, 20.0, 18);
    EXPECT_EQ(range.sizes, 5U);
    EXPECT_NEAR(range.efficiencies.qext, middle.efficiencies.qext, kNarrowRangeTolerance);
    EXPECT_NEAR(range.efficiencies.qsca, middle.efficiencies.qsca, kNarrowRangeTolerance);
    EXPECT_NEAR(range.efficiencies.qback, middle.efficiencies.qback, kNarrowRangeTolerance * 10.0);
    EXPECT_NEAR(range.efficiencies.g, middle.efficiencies.g, kNarrowRangeTolerance);
    EXPECT_NEAR(range.xMean, 20.0, 1e-8);
    for (std::size_t bin = 0; bin < 18; ++bin) {
        EXPECT_NEAR(range.bins.fraction[bin], middle.bins.fraction[bin], kNarrowRangeTolerance) << bin;
    }
}

// Sums of two terms: exact to a few ulp.
constexpr double kByHandTolerance = 1e-14;

TEST(MieAverage, TwoSizesWeightedByHand) {
    // count = 2 midpoints of [4, 12]: x = 6 and x = 10.
    const MieResult average = mieAverageOverSizeParameter(kWater, 4.0, 12.0, 2, 9);
    const MieResult small = mieSphere(kWater, 6.0, 9);
    const MieResult large = mieSphere(kWater, 10.0, 9);
    const double ws = 36.0, wl = 100.0;  // geometric cross-sections, x^2
    const auto byArea = [&](double s, double l) { return (ws * s + wl * l) / (ws + wl); };
    const MieEfficiencies& qs = small.efficiencies;
    const MieEfficiencies& ql = large.efficiencies;
    EXPECT_NEAR(average.efficiencies.qext, byArea(qs.qext, ql.qext), kByHandTolerance);
    EXPECT_NEAR(average.efficiencies.qsca, byArea(qs.qsca, ql.qsca), kByHandTolerance);
    EXPECT_NEAR(average.efficiencies.qabs, byArea(qs.qabs, ql.qabs), kByHandTolerance);
    EXPECT_NEAR(average.efficiencies.qback, byArea(qs.qback, ql.qback), kByHandTolerance);
    // g by scattering cross-section, x^2 Q_sca.
    const double g = (ws * qs.qsca * qs.g + wl * ql.qsca * ql.g) / (ws * qs.qsca + wl * ql.qsca);
    EXPECT_NEAR(average.efficiencies.g, g, kByHandTolerance);
    EXPECT_NEAR(average.xMean, byArea(6.0, 10.0), kByHandTolerance);
    EXPECT_EQ(average.sizes, 2U);
    for (std::size_t bin = 0; bin < 9; ++bin) {
        EXPECT_NEAR(average.bins.fraction[bin], byArea(small.bins.fraction[bin], large.bins.fraction[bin]),
                    kByHandTolerance);
        EXPECT_NEAR(average.bins.s34[bin], byArea(small.bins.s34[bin], large.bins.s34[bin]), kByHandTolerance);
    }
}

TEST(MieAverage, RadiusDistributionSampledAtProbabilityMidpoints) {
    const double wavenumber = 10.0;
    // Uniform radii on [1, 1.5]: x on [10, 15], 50 sizes at the default spacing of 0.1 (over the 1e-3 to
    // 1 - 1e-3 quantiles, 4.99 of x: 50 midpoints), weighted by cross-section: xMean = E[x^3] / E[x^2].
    const MieResult cloud = mieAverageOverRadii(kWater, RadiusDistribution::uniform(1.0, 1.5), wavenumber, 0);
    EXPECT_EQ(cloud.sizes, 50U);
    double third = 0.0, second = 0.0;
    for (std::size_t j = 0; j < 50; ++j) {
        const double x = wavenumber * (1.0 + 0.5 * (static_cast<double>(j) + 0.5) / 50.0);
        third += x * x * x;
        second += x * x;
    }
    EXPECT_NEAR(cloud.xMean, third / second, 1e-12);
    // A narrow lognormal gets the minimum sample count; the sum of its bins is its Q_sca.
    const MieResult narrow = mieAverageOverRadii(kWater, RadiusDistribution::lognormal(1.0, 1e-3), wavenumber, 12);
    EXPECT_EQ(narrow.sizes, 32U);
    double sum = 0.0;
    for (const double value : narrow.bins.fraction) sum += value;
    EXPECT_NEAR(sum / narrow.efficiencies.qsca, 1.0, 1e-10);
}

TEST(MieAverage, DefaultSizeCountSamplesTheRippleAndIsBounded) {
    EXPECT_EQ(defaultSizeParameterCount(10.0, 11.0), 10U);
    EXPECT_EQ(defaultSizeParameterCount(5.0, 5.0), 1U);
    EXPECT_EQ(defaultSizeParameterCount(5.0, 5.01), 1U);
    EXPECT_EQ(defaultSizeParameterCount(1.0, 1e4), 1000U);
}

TEST(MieAverage, SameResultOnOneThreadAndOnSeveral) {
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const MieResult serial = mieAverageOverSizeParameter(kWater, 30.0, 40.0, 17, 36);
    omp_set_num_threads(std::max(threads, 2));
    const MieResult parallel = mieAverageOverSizeParameter(kWater, 30.0, 40.0, 17, 36);
    omp_set_num_threads(threads);
    expectIdentical(serial, parallel);
}

}  // namespace
}  // namespace dropscope
