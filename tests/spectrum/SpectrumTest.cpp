#include "spectrum/KolmogorovSmirnov.hpp"
#include "spectrum/Spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

namespace dropscope {
namespace {

// Kolmogorov-Smirnov tests draw this many wavelengths each, from a fixed seed: deterministic, so a pass is a
// pass on every machine; the critical value says how unlikely a failure would be for a correct sampler.
constexpr int kSamples = 20000;
// The asymptotic Kolmogorov distribution's 99 % quantile: D > 1.628 / sqrt(N) with probability 0.01 for
// samples of the hypothesised distribution (N = 20000: D < 0.0115).
constexpr double kKolmogorov99 = 1.628;
// Chi-square with 2 degrees of freedom (three lines) exceeds 13.816 with probability 0.001.
constexpr double kChiSquare2Dof999 = 13.816;
// Probabilities built from sums and one division of a few doubles <= 1: a few rounding errors of 1.1e-16.
constexpr double kRounding = 1e-15;
// cdf(sample(u)) = u: both invert the same piecewise-linear density; the quadratic's root carries a few
// rounding errors relative to the segment's share, far below this.
constexpr double kInverseSlack = 1e-12;
// Wien's displacement constant b = hc / (k * 4.965114231744276...), CODATA 2018, in m K.
constexpr double kWienDisplacement = 2.897771955e-3;
// The maximum of a smooth function located by comparing its values is good to ~sqrt(machine epsilon)
// (1.5e-8) relatively; 1e-6 still catches a radiation constant wrong in its 7th digit.
constexpr double kWienRelative = 1e-6;

std::vector<double> draw(const Spectrum& spectrum, int count, std::uint64_t seed) {
    std::mt19937_64 generator(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> samples;
    samples.reserve(count);
    for (int i = 0; i < count; ++i) {
        double u = uniform(generator);
        while (u == 0.0) u = uniform(generator);  // u in (0, 1)
        samples.push_back(spectrum.sample(u));
    }
    return samples;
}

using test::ksStatistic;

double ksCritical(int count) { return kKolmogorov99 / std::sqrt(static_cast<double>(count)); }

// Planck's law written out here, independently of the engine: lambda^-5 / (exp(hc/(lambda k T)) - 1).
double planck(double nm, double kelvin) {
    const double metres = nm * 1e-9;
    return 1.0 / (std::pow(metres, 5) * std::expm1(1.438776877e-2 / (metres * kelvin)));
}

// The integral of Planck's law over [a, b] by 5-point Gauss-Legendre on `pieces` equal pieces.
double integratePlanck(double kelvin, double a, double b, int pieces) {
    constexpr std::array<double, 5> nodes{0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640,
                                          -0.9061798459386640};
    constexpr std::array<double, 5> weights{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                            0.2369268850561891, 0.2369268850561891};
    const double h = (b - a) / pieces;
    double sum = 0.0;
    for (int p = 0; p < pieces; ++p) {
        const double mid = a + (p + 0.5) * h;
        for (std::size_t j = 0; j < nodes.size(); ++j) sum += weights[j] * planck(mid + 0.5 * h * nodes[j], kelvin);
    }
    return 0.5 * h * sum;
}

// The reference cdf of a blackbody over [lo, hi] at `points` equally spaced wavelengths.
struct ReferenceCdf {
    std::vector<double> nm;
    std::vector<double> cdf;
    double operator()(double x) const {
        // Linear between the reference points: used only by the KS test, whose resolution (1e-2) is far
        // coarser than this interpolation's error at 4000 points.
        const auto above = std::upper_bound(nm.begin(), nm.end(), x);
        if (above == nm.begin()) return 0.0;
        if (above == nm.end()) return 1.0;
        const std::size_t i = above - nm.begin() - 1;
        const double t = (x - nm[i]) / (nm[i + 1] - nm[i]);
        return cdf[i] + t * (cdf[i + 1] - cdf[i]);
    }
};

ReferenceCdf referenceBlackbodyCdf(double kelvin, double lo, double hi, int points) {
    ReferenceCdf reference;
    double running = 0.0;
    for (int i = 0; i <= points; ++i) {
        const double x = lo + (hi - lo) * i / points;
        if (i > 0) running += integratePlanck(kelvin, reference.nm.back(), x, 8);
        reference.nm.push_back(x);
        reference.cdf.push_back(running);
    }
    for (double& value : reference.cdf) value /= running;
    return reference;
}

// The test's own closed form for the table (400, 0), (500, 2), (550, 2), (600, 0.5), (700, 0): the
// integral of the piecewise-linear density, normalised by its total 100 + 100 + 62.5 + 25 = 287.5.
const std::vector<std::pair<double, double>> kTablePoints{{400, 0}, {500, 2}, {550, 2}, {600, 0.5}, {700, 0}};
double tableCdf(double x) {
    double area = 0.0;
    for (std::size_t k = 0; k + 1 < kTablePoints.size(); ++k) {
        const auto [x0, w0] = kTablePoints[k];
        const auto [x1, w1] = kTablePoints[k + 1];
        const double s = std::clamp(x, x0, x1) - x0;
        area += w0 * s + 0.5 * (w1 - w0) / (x1 - x0) * s * s;
    }
    return area / 287.5;
}

TEST(Spectrum, LinesAreDrawnWithTheirWeights) {
    const Spectrum spectrum = Spectrum::lines({{650, 3.5}, {450, 1}, {532, 2}});
    const std::vector<double> samples = draw(spectrum, 3 * kSamples, 1);
    const std::array<double, 3> wavelengths{450, 532, 650};
    const std::array<double, 3> probabilities{1 / 6.5, 2 / 6.5, 3.5 / 6.5};
    double chiSquare = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double observed = static_cast<double>(std::count(samples.begin(), samples.end(), wavelengths[i]));
        const double expected = probabilities[i] * static_cast<double>(samples.size());
        chiSquare += (observed - expected) * (observed - expected) / expected;
    }
    EXPECT_EQ(std::count_if(samples.begin(), samples.end(), [](double x) { return x != 450 && x != 532 && x != 650; }),
              0);
    EXPECT_LT(chiSquare, kChiSquare2Dof999);
}

TEST(Spectrum, LineProbabilitiesAreTheWeightsShares) {
    const Spectrum spectrum = Spectrum::lines({{650, 3.5}, {450, 1}, {532, 2}});
    EXPECT_EQ(spectrum.cdf(449.999), 0.0);
    EXPECT_NEAR(spectrum.cdf(450), 1 / 6.5, kRounding);
    EXPECT_NEAR(spectrum.cdf(532) - spectrum.cdf(531.999), 2 / 6.5, kRounding);
    EXPECT_NEAR(spectrum.cdf(650) - spectrum.cdf(649.999), 3.5 / 6.5, kRounding);
    EXPECT_EQ(spectrum.cdf(650), 1.0);
    // The scene's order is kept for writing back.
    EXPECT_EQ(spectrum.pointsNm().front().first, 650);
    // sample() inverts cdf(): u just below and above 1/6.5 gives 450 and 532.
    EXPECT_EQ(spectrum.sample(1 / 6.5 - 1e-9), 450);
    EXPECT_EQ(spectrum.sample(1 / 6.5 + 1e-9), 532);
    EXPECT_EQ(spectrum.sample(3 / 6.5 + 1e-9), 650);
}

TEST(Spectrum, ASingleLineDrawsNoRandomNumber) {
    const Spectrum single = Spectrum::line(589.0);
    EXPECT_FALSE(single.drawsRandomNumbers());
    EXPECT_EQ(single.sample(1e-9), 589.0);
    EXPECT_EQ(single.sample(0.5), 589.0);
    EXPECT_EQ(single.sample(1 - 1e-9), 589.0);
    EXPECT_EQ(Spectrum{}, Spectrum::line(532.0));
    EXPECT_FALSE(Spectrum{}.drawsRandomNumbers());
    // The same wavelength twice is still one line.
    EXPECT_FALSE(Spectrum::lines({{500, 1}, {500, 2}}).drawsRandomNumbers());
    EXPECT_TRUE(Spectrum::lines({{500, 1}, {501, 2}}).drawsRandomNumbers());
    EXPECT_TRUE(Spectrum::uniform(400, 700).drawsRandomNumbers());
    EXPECT_TRUE(Spectrum::table(kTablePoints).drawsRandomNumbers());
    EXPECT_TRUE(Spectrum::sun().drawsRandomNumbers());
}

TEST(Spectrum, UniformPassesKolmogorovSmirnov) {
    const Spectrum spectrum = Spectrum::uniform(400, 700);
    const double d = ksStatistic(draw(spectrum, kSamples, 2), [](double x) { return (x - 400) / 300; });
    EXPECT_LT(d, ksCritical(kSamples));
    EXPECT_EQ(spectrum.sample(0.25), 475.0);
    EXPECT_EQ(spectrum.cdf(550), 0.5);
}

TEST(Spectrum, TablePassesKolmogorovSmirnovAgainstItsClosedForm) {
    const Spectrum spectrum = Spectrum::table(kTablePoints);
    EXPECT_LT(ksStatistic(draw(spectrum, kSamples, 3), tableCdf), ksCritical(kSamples));
    // The exact inverse: the test's own cdf of each sample gives back u, in rising, falling and flat segments.
    for (double u = 0.001; u < 1.0; u += 0.001) {
        EXPECT_NEAR(tableCdf(spectrum.sample(u)), u, kInverseSlack) << "u = " << u;
        EXPECT_NEAR(spectrum.cdf(spectrum.sample(u)), u, kInverseSlack) << "u = " << u;
    }
    EXPECT_NEAR(spectrum.cdf(500), 100 / 287.5, kRounding);
    EXPECT_NEAR(spectrum.cdf(575), tableCdf(575), kRounding);
}

TEST(Spectrum, BlackbodyPassesKolmogorovSmirnov) {
    const Spectrum spectrum = Spectrum::blackbody(3000, 300, 2500);
    const ReferenceCdf reference = referenceBlackbodyCdf(3000, 300, 2500, 4000);
    EXPECT_LT(ksStatistic(draw(spectrum, kSamples, 4), reference), ksCritical(kSamples));
}

TEST(Spectrum, SunPassesKolmogorovSmirnov) {
    const Spectrum spectrum = Spectrum::sun();
    EXPECT_EQ(spectrum.kind(), Spectrum::Kind::Sun);
    EXPECT_EQ(spectrum.kelvin(), kSunKelvin);
    EXPECT_EQ(spectrum.boundsNm(), kSunRangeNm);
    EXPECT_FALSE(spectrum == Spectrum::blackbody(kSunKelvin, kSunRangeNm.first, kSunRangeNm.second));
    const ReferenceCdf reference = referenceBlackbodyCdf(kSunKelvin, kSunRangeNm.first, kSunRangeNm.second, 4000);
    EXPECT_LT(ksStatistic(draw(spectrum, kSamples, 5), reference), ksCritical(kSamples));
}

// The tabulated cdf against Gauss-Legendre integration of Planck's law (2000 pieces between test points:
// error ~1e-15), at wavelengths that are not grid nodes: within the grid's stated error, kBlackbodyCdfError.
TEST(Spectrum, BlackbodyCdfMatchesPlancksLawIntegrated) {
    struct Case {
        double kelvin, lo, hi;
    };
    for (const Case& c : {Case{kSunKelvin, 380, 780}, Case{3000, 300, 2500}, Case{1500, 380, 780},
                          Case{20000, 200, 1000}, Case{300, 2000, 50000}}) {
        const Spectrum spectrum = Spectrum::blackbody(c.kelvin, c.lo, c.hi);
        std::vector<double> points{c.lo};
        for (int i = 0; i < 97; ++i) points.push_back(c.lo + (c.hi - c.lo) * (i + 0.3183) / 97);  // off the grid
        points.push_back(c.hi);
        std::vector<double> integral{0.0};
        for (std::size_t i = 1; i < points.size(); ++i) {
            integral.push_back(integral.back() + integratePlanck(c.kelvin, points[i - 1], points[i], 2000));
        }
        double worst = 0.0;
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            worst = std::max(worst, std::abs(spectrum.cdf(points[i]) - integral[i] / integral.back()));
        }
        EXPECT_LT(worst, kBlackbodyCdfError) << c.kelvin << " K over [" << c.lo << ", " << c.hi << "] nm";
    }
}

TEST(Spectrum, PlanckDensityPeaksWhereWienSays) {
    for (double kelvin : {kSunKelvin, 3000.0, 10000.0}) {
        // Golden-section search for the maximum over [100, 3000] nm.
        const double ratio = (std::sqrt(5.0) - 1) / 2;
        double a = 100, b = 3000;
        while (b - a > 1e-9 * a) {
            const double c = b - ratio * (b - a);
            const double d = a + ratio * (b - a);
            if (planckDensity(c, kelvin) > planckDensity(d, kelvin)) {
                b = d;
            } else {
                a = c;
            }
        }
        const double peakMetres = 0.5 * (a + b) * 1e-9;
        EXPECT_NEAR(peakMetres * kelvin / kWienDisplacement, 1.0, kWienRelative) << kelvin << " K";
        // And the density is Planck's law itself.
        EXPECT_NEAR(planckDensity(500, kelvin) / planck(500, kelvin), 1.0, kRounding);
    }
}

TEST(Spectrum, SampleIsMonotoneInU) {
    for (const Spectrum& spectrum :
         {Spectrum::lines({{650, 3.5}, {450, 1}, {532, 2}}), Spectrum::uniform(400, 700), Spectrum::table(kTablePoints),
          Spectrum::blackbody(1500, 380, 780), Spectrum::sun()}) {
        double previous = spectrum.sample(0.0);
        for (int i = 1; i <= 100000; ++i) {
            const double next = spectrum.sample(i / 100000.0);
            ASSERT_GE(next, previous) << "kind " << static_cast<int>(spectrum.kind()) << ", u = " << i / 100000.0;
            previous = next;
        }
    }
}

TEST(Spectrum, RangeIsWhereLightIsEmitted) {
    EXPECT_EQ(Spectrum::line(589).rangeNm(), (std::pair<double, double>{589, 589}));
    EXPECT_EQ(Spectrum::lines({{650, 3.5}, {450, 1}, {532, 2}}).rangeNm(), (std::pair<double, double>{450, 650}));
    EXPECT_EQ(Spectrum::uniform(400, 700).rangeNm(), (std::pair<double, double>{400, 700}));
    EXPECT_EQ(Spectrum::table(kTablePoints).rangeNm(), (std::pair<double, double>{400, 700}));
    // Zero weights at both ends: light only between the last leading and the first trailing zero.
    EXPECT_EQ(Spectrum::table({{400, 0}, {450, 0}, {500, 1}, {600, 0}, {700, 0}}).rangeNm(),
              (std::pair<double, double>{450, 600}));
    EXPECT_EQ(Spectrum::blackbody(3000, 300, 2500).rangeNm(), (std::pair<double, double>{300, 2500}));
    EXPECT_EQ(Spectrum::sun().rangeNm(), kSunRangeNm);
    // Samples stay inside it.
    const Spectrum padded = Spectrum::table({{400, 0}, {450, 0}, {500, 1}, {600, 0}, {700, 0}});
    EXPECT_EQ(padded.sample(0.0), 450);
    EXPECT_EQ(padded.sample(1.0), 600);
}

void expectMessage(const std::function<void()>& make, const std::string& message) {
    try {
        make();
        ADD_FAILURE() << "no error, expected: " << message;
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(error.what(), message);
    }
}

TEST(Spectrum, RefusesWhatIsNotASpectrumSayingWhy) {
    const double nan = std::nan("");
    const double inf = HUGE_VAL;
    expectMessage([] { Spectrum::lines({}); }, "a lines spectrum needs at least one line");
    expectMessage([] { Spectrum::line(-5); }, "a line's wavelength must be finite and > 0 nm (got -5)");
    expectMessage([=] { Spectrum::line(nan); }, "a line's wavelength must be finite and > 0 nm (got nan)");
    expectMessage([=] { Spectrum::lines({{500, inf}}); }, "a line's weight must be finite and > 0 (got inf at 500 nm)");
    expectMessage(
        [] {
            Spectrum::lines({{500, 1}, {600, 0}});
        },
        "a line's weight must be finite and > 0 (got 0 at 600 nm)");
    expectMessage([] { Spectrum::uniform(700, 400); }, "a uniform spectrum needs lo < hi (700 >= 400 nm)");
    expectMessage([] { Spectrum::uniform(500, 500); }, "a uniform spectrum needs lo < hi (500 >= 500 nm)");
    expectMessage([] { Spectrum::uniform(0, 400); }, "a uniform spectrum lo must be finite and > 0 nm (got 0)");
    expectMessage([=] { Spectrum::uniform(400, inf); }, "a uniform spectrum hi must be finite and > 0 nm (got inf)");
    expectMessage([] { Spectrum::table({{500, 1}}); }, "a table spectrum needs at least 2 points");
    expectMessage(
        [] {
            Spectrum::table({{500, 1}, {500, 2}});
        },
        "a table's wavelengths must be strictly ascending (500 then 500 nm)");
    expectMessage(
        [] {
            Spectrum::table({{500, 1}, {600, -1}});
        },
        "a table's weight must be finite and >= 0 (got -1 at 600 nm)");
    expectMessage([] { Spectrum::table({{500, 0}, {600, 0}}); }, "a table spectrum needs a weight > 0");
    expectMessage(
        [] {
            Spectrum::table({{-1, 1}, {600, 0}});
        },
        "a table's wavelength must be finite and > 0 nm (got -1)");
    expectMessage([] { Spectrum::blackbody(0, 400, 700); },
                  "a blackbody's temperature must be finite and > 0 K (got 0)");
    expectMessage([=] { Spectrum::blackbody(nan, 400, 700); },
                  "a blackbody's temperature must be finite and > 0 K (got nan)");
    expectMessage([] { Spectrum::blackbody(5000, 700, 400); }, "a blackbody spectrum needs lo < hi (700 >= 400 nm)");
    expectMessage([] { Spectrum::blackbody(0.05, 380, 780); },
                  "a blackbody at 0.05 K emits in too narrow a band of [380, 780] nm to tabulate");
}

}  // namespace
}  // namespace dropscope
