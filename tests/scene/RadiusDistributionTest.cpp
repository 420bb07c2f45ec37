// Radius distributions of droplet clouds against their closed forms. Each statistic of n = 1e5
// samples is compared with a tolerance of 5 standard errors: for a fixed seed the test is
// deterministic, and a correct sampler fails a 5-sigma check with probability ~6e-7 per seed.
#include "scene/RadiusDistribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace dropscope {
namespace {

constexpr std::size_t kSamples = 100000;
const double kRootN = std::sqrt(static_cast<double>(kSamples));

std::vector<double> draw(const RadiusDistribution& distribution, std::uint64_t seed = 1) {
    RandomStream random(seed, 0);
    std::vector<double> radii(kSamples);
    for (double& r : radii) r = distribution.sample(random);
    return radii;
}

double mean(const std::vector<double>& values) {
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double standardDeviation(const std::vector<double>& values) {
    const double m = mean(values);
    double sum = 0.0;
    for (const double v : values) sum += (v - m) * (v - m);
    return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

double median(std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// Fraction of values <= x, and 5 standard errors of a fraction near p.
double fractionAtMost(const std::vector<double>& values, double x) {
    return static_cast<double>(std::count_if(values.begin(), values.end(), [&](double v) { return v <= x; })) /
           static_cast<double>(values.size());
}
double fractionTolerance(double p) { return 5.0 * std::sqrt(p * (1.0 - p)) / kRootN; }

std::vector<double> logarithms(const std::vector<double>& values) {
    std::vector<double> logs(values.size());
    std::transform(values.begin(), values.end(), logs.begin(), [](double v) { return std::log(v); });
    return logs;
}

TEST(RandomStream, ConversionsAreExactAndInRange) {
    RandomStream random(42, 3);
    for (int i = 0; i < 100000; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        ASSERT_EQ(std::ldexp(u, 53), std::floor(std::ldexp(u, 53)));  // a multiple of 2^-53
        const double v = random.openUniform();
        ASSERT_GT(v, 0.0);
        ASSERT_LT(v, 1.0);
        ASSERT_EQ(std::fmod(std::ldexp(v, 53), 2.0), 1.0);  // an odd multiple of 2^-53
        ASSERT_EQ(1.0 - (1.0 - v), v);                      // so 1 - v is exact too
    }
}

TEST(RandomStream, StreamsAndSeedsAreDistinctAndRepeatable) {
    RandomStream a(7, 0);
    RandomStream b(7, 0);
    RandomStream otherStream(7, 1);
    RandomStream otherSeed(8, 0);
    for (int i = 0; i < 100; ++i) {
        const std::uint64_t bits = a.bits();
        EXPECT_EQ(bits, b.bits());
        EXPECT_NE(bits, otherStream.bits());
        EXPECT_NE(bits, otherSeed.bits());
    }
}

// Reference values of Phi^-1 to 16 digits, computed with mpmath at 50 digits.
TEST(NormalQuantile, MatchesReferenceValuesAndInvertsTheCdf) {
    EXPECT_EQ(normalQuantile(0.5), 0.0);
    EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 4e-16 * 1.96);
    EXPECT_NEAR(normalQuantile(0.3), -0.5244005127080407, 4e-16);
    EXPECT_NEAR(normalQuantile(1e-10), -6.361340902404056, 4e-16 * 6.4);
    EXPECT_NEAR(normalQuantile(1e-300), -37.0470962993612, 1e-15 * 37.0);
    for (double p = 1e-15; p < 0.5; p *= 1.7) {
        EXPECT_NEAR(normalCdf(normalQuantile(p)) / p, 1.0, 1e-13) << "p = " << p;
    }
}

// For the probabilities openUniform gives, 1 - p is exact, and so is the symmetry of the tails.
TEST(NormalQuantile, IsExactlySymmetricOnOpenUniformValues) {
    RandomStream random(5, 0);
    std::vector<double> probabilities{0x1p-53, 3 * 0x1p-53, 1001 * 0x1p-53, 0.5 - 0x1p-53};
    for (int i = 0; i < 10000; ++i) probabilities.push_back(random.openUniform());
    for (const double p : probabilities) ASSERT_EQ(normalQuantile(1.0 - p), -normalQuantile(p)) << "p = " << p;
}

TEST(RadiusDistribution, FixedIsOneValueAndZeroSigmaLognormalIsItsMedian) {
    for (const double r : draw(RadiusDistribution::fixed(0.25))) ASSERT_EQ(r, 0.25);
    for (const double r : draw(RadiusDistribution::lognormal(0.3, 0.0))) ASSERT_EQ(r, 0.3);
}

TEST(RadiusDistribution, UniformStaysInItsBoundsWithTheRightMean) {
    const double a = 0.01;
    const double b = 0.05;
    const std::vector<double> radii = draw(RadiusDistribution::uniform(a, b));
    EXPECT_GT(*std::min_element(radii.begin(), radii.end()), a);
    EXPECT_LT(*std::max_element(radii.begin(), radii.end()), b);
    EXPECT_NEAR(mean(radii), 0.5 * (a + b), 5.0 * (b - a) / std::sqrt(12.0) / kRootN);
    EXPECT_NEAR(fractionAtMost(radii, a + 0.25 * (b - a)), 0.25, fractionTolerance(0.25));
}

// ln r ~ N(ln m, sigma^2): the median is m, ln r has standard deviation sigma, and
// P(r <= m e^sigma) = Phi(1).
TEST(RadiusDistribution, LognormalHasItsMedianAndLogSpread) {
    const double m = 0.01;
    const double sigma = 0.3;
    const std::vector<double> radii = draw(RadiusDistribution::lognormal(m, sigma));
    const std::vector<double> logs = logarithms(radii);
    // The sample median of ln r has standard error sqrt(pi/2) sigma / sqrt(n).
    EXPECT_NEAR(std::log(median(radii)), std::log(m), 5.0 * 1.2533 * sigma / kRootN);
    EXPECT_NEAR(mean(logs), std::log(m), 5.0 * sigma / kRootN);
    // The sample standard deviation has standard error sigma / sqrt(2n).
    EXPECT_NEAR(standardDeviation(logs), sigma, 5.0 * sigma / std::sqrt(2.0) / kRootN);
    const double p = normalCdf(1.0);
    EXPECT_NEAR(fractionAtMost(radii, m * std::exp(sigma)), p, fractionTolerance(p));
    const double q = normalCdf(-2.0);
    EXPECT_NEAR(fractionAtMost(radii, m * std::exp(-2.0 * sigma)), q, fractionTolerance(q));
}

// P(r <= X) = 1 - 1/e = 63.2 %, and E[r] = X Gamma(1 + 1/q).
TEST(RadiusDistribution, RosinRammlerHasItsCharacteristicRadiusAndMean) {
    const double scale = 0.02;
    for (const double shape : {1.5, 3.0}) {
        const std::vector<double> radii = draw(RadiusDistribution::rosinRammler(scale, shape));
        const double p = 1.0 - std::exp(-1.0);
        EXPECT_NEAR(fractionAtMost(radii, scale), p, fractionTolerance(p)) << "shape " << shape;
        const double g1 = std::tgamma(1.0 + 1.0 / shape);
        const double g2 = std::tgamma(1.0 + 2.0 / shape);
        const double expectedMean = scale * g1;
        const double expectedSd = scale * std::sqrt(g2 - g1 * g1);
        EXPECT_NEAR(mean(radii), expectedMean, 5.0 * expectedSd / kRootN) << "shape " << shape;
        // The sample SD has standard error SD sqrt((kurtosis - 1) / 4n), below SD / sqrt(n) for these
        // shapes (kurtosis 4.4 at q = 1.5, 2.7 at q = 3).
        EXPECT_NEAR(standardDeviation(radii), expectedSd, 5.0 * expectedSd / kRootN) << "shape " << shape;
    }
}

// Truncated to [a, b], P(r <= x) = (F(x) - F(a)) / (F(b) - F(a)).
TEST(RadiusDistribution, TruncatedLognormalHonoursItsBoundsAndShape) {
    const double m = 0.01;
    const double sigma = 0.5;
    const double a = 0.008;
    const double b = 0.03;
    const RadiusDistribution distribution = RadiusDistribution::lognormal(m, sigma, a, b);
    EXPECT_EQ(distribution.min(), a);
    EXPECT_EQ(distribution.max(), b);
    const std::vector<double> radii = draw(distribution);
    EXPECT_GE(*std::min_element(radii.begin(), radii.end()), a);
    EXPECT_LE(*std::max_element(radii.begin(), radii.end()), b);
    const auto cdf = [&](double r) { return normalCdf(std::log(r / m) / sigma); };
    for (const double x : {0.009, 0.01, 0.015, 0.025}) {
        const double p = (cdf(x) - cdf(a)) / (cdf(b) - cdf(a));
        EXPECT_NEAR(fractionAtMost(radii, x), p, fractionTolerance(p)) << "x = " << x;
    }
}

// Bounds far above the median are sampled on the upper tail, where the probabilities keep their
// digits: a lognormal beyond 4 sigma and a Rosin-Rammler beyond twice its scale.
TEST(RadiusDistribution, TruncationsInTheUpperTailKeepTheirShape) {
    const double m = 1.0;
    const double sigma = 0.5;
    const double a = std::exp(4.0 * sigma);
    const std::vector<double> lognormal = draw(RadiusDistribution::lognormal(m, sigma, a));
    EXPECT_GE(*std::min_element(lognormal.begin(), lognormal.end()), a);
    // P(z <= 4.5 | z >= 4) = 1 - Phi(-4.5) / Phi(-4).
    const double p = 1.0 - normalCdf(-4.5) / normalCdf(-4.0);
    EXPECT_NEAR(fractionAtMost(lognormal, std::exp(4.5 * sigma)), p, fractionTolerance(p));

    const double scale = 0.02;
    const double shape = 2.0;
    const double lower = 2.0 * scale;
    const std::vector<double> rosinRammler = draw(RadiusDistribution::rosinRammler(scale, shape, lower, 3.0 * scale));
    EXPECT_GE(*std::min_element(rosinRammler.begin(), rosinRammler.end()), lower);
    EXPECT_LE(*std::max_element(rosinRammler.begin(), rosinRammler.end()), 3.0 * scale);
    // t = (r/X)^q is exponential: P(t <= 5 | 4 <= t <= 9) = (1 - e^-1) / (1 - e^-5).
    const double q = (1.0 - std::exp(-1.0)) / (1.0 - std::exp(-5.0));
    EXPECT_NEAR(fractionAtMost(rosinRammler, scale * std::sqrt(5.0)), q, fractionTolerance(q));
}

TEST(RadiusDistribution, TruncationKeepingAlmostNothingIsRefused) {
    EXPECT_THROW(RadiusDistribution::lognormal(1.0, 0.5, std::exp(5.5 * 0.5)), std::invalid_argument);
    EXPECT_THROW(RadiusDistribution::rosinRammler(1.0, 2.0, 0.0, 1e-4), std::invalid_argument);
    EXPECT_NO_THROW(RadiusDistribution::rosinRammler(1.0, 2.0, 0.0, 1e-2));
}

// sample() is quantile() of the stream's next openUniform() draw, bit for bit, for every kind and truncation
// (the Mie averages read the distribution through quantile(), docs/mie.md); a fixed one draws nothing.
TEST(RadiusDistribution, SampleIsTheQuantileOfTheSameDraw) {
    const RadiusDistribution distributions[] = {
        RadiusDistribution::uniform(0.5, 2.0),
        RadiusDistribution::lognormal(1.0, 0.5),
        RadiusDistribution::lognormal(1.0, 0.5, 0.8, 1.5),
        RadiusDistribution::lognormal(1.0, 0.5, std::exp(4.0 * 0.5)),
        RadiusDistribution::rosinRammler(0.02, 2.0),
        RadiusDistribution::rosinRammler(0.02, 2.0, 0.04, 0.06),
    };
    for (const RadiusDistribution& distribution : distributions) {
        RandomStream sampled(7, 3);
        RandomStream drawn(7, 3);
        for (int i = 0; i < 1000; ++i) {
            const double radius = distribution.sample(sampled);
            ASSERT_EQ(radius, distribution.quantile(drawn.openUniform())) << i;
        }
    }
    RandomStream untouched(7, 3);
    RandomStream reference(7, 3);
    EXPECT_EQ(RadiusDistribution::fixed(2.5).sample(untouched), 2.5);
    EXPECT_EQ(RadiusDistribution::fixed(2.5).quantile(0.3), 2.5);
    EXPECT_EQ(untouched.openUniform(), reference.openUniform());
    EXPECT_THROW(RadiusDistribution::uniform(1.0, 2.0).quantile(1.0), std::invalid_argument);
    EXPECT_THROW(RadiusDistribution::uniform(1.0, 2.0).quantile(0.0), std::invalid_argument);
    // The quantile is monotone and honours the truncation at its ends.
    const RadiusDistribution truncated = RadiusDistribution::lognormal(1.0, 0.5, 0.8, 1.5);
    EXPECT_GE(truncated.quantile(1e-12), 0.8);
    EXPECT_LE(truncated.quantile(1.0 - 1e-12), 1.5);
    EXPECT_LT(truncated.quantile(0.25), truncated.quantile(0.75));
}

}  // namespace
}  // namespace dropscope
