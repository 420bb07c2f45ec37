// The rainbows of rainbow.json (a clear water sphere under a beam) against Descartes' minimum
// deviation, and Alexander's dark band between them (docs/validation.md, "The rainbows").
#include "Descartes.hpp"
#include "ValidationRuns.hpp"

#include "transport/SphereRayOptics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace dropscope::validation {
namespace {

// 0.1-degree bins, as docs/validation.md reads angular.csv: fine enough to place a bow to its bin.
constexpr int kBins = 1800;
constexpr double kBinDeg = 180.0 / kBins;

struct Window {
    double loDeg;
    double hiDeg;
};
// Each bow's search window: its bright side and some of its dark side, clear of the other bow.
constexpr Window kPrimaryWindow{135, 145};
constexpr Window kSecondaryWindow{125, 132};
// Alexander's band and its two sides, each window a few degrees clear of the bows' caustics.
constexpr Window kDarkBand{130, 137};
constexpr Window kInsidePrimary{139, 146};
constexpr Window kOutsideSecondary{122, 128};
// "Dark" means at least twice as dark as either side: geometric optics gives about 20 on the primary's
// side and 3.6 on the secondary's (computed below), so this holds with margin at any photon count.
constexpr double kAlexanderContrast = 2.0;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
int firstBin(const Window& window) { return static_cast<int>(std::lround(window.loDeg / kBinDeg)); }
int endBin(const Window& window) { return static_cast<int>(std::lround(window.hiDeg / kBinDeg)); }

// Geometric optics puts an inverse square-root singularity at the caustic, on its bright side: the
// share of it in [lo, hi] is the integral of |θ − θR|^(-1/2) over the part of the bin on that side.
double causticWeight(double loDeg, double hiDeg, const Caustic& caustic) {
    const auto root = [](double x) { return 2 * std::sqrt(std::max(0.0, x)); };
    const double at = caustic.scatteringDeg;
    return caustic.brightAbove ? root(hiDeg - at) - root(loDeg - at) : root(at - loDeg) - root(at - hiDeg);
}

std::string binName(int bin) { return formatted(bin * kBinDeg, "%.1f") + "-" + formatted((bin + 1) * kBinDeg, "%.1f"); }

// The bin of the window that holds the most of the caustic (the doc's argument), against the bin of
// the run with the largest fraction per steradian.
void expectBrightestBinAtTheCaustic(const std::string& name, int k, const Window& window) {
    const double n = loadSphereScene("rainbow").relativeIndex();
    const Caustic caustic = descartes(n, k);
    const TraceResult& run = validationRun("rainbow", kBins);
    const std::vector<double> radiance = test::angular(run).columns().perSteradian;
    const auto& escapes = test::angular(run).escapes();

    int expected = firstBin(window);
    int measured = firstBin(window);
    for (int bin = firstBin(window); bin < endBin(window); ++bin) {
        if (causticWeight(bin * kBinDeg, (bin + 1) * kBinDeg, caustic) >
            causticWeight(expected * kBinDeg, (expected + 1) * kBinDeg, caustic)) {
            expected = bin;
        }
        if (radiance[static_cast<std::size_t>(bin)] > radiance[static_cast<std::size_t>(measured)]) measured = bin;
    }
    int runnerUp = measured == firstBin(window) ? measured + 1 : firstBin(window);
    for (int bin = firstBin(window); bin < endBin(window); ++bin) {
        if (bin != measured && radiance[static_cast<std::size_t>(bin)] > radiance[static_cast<std::size_t>(runnerUp)]) {
            runnerUp = bin;
        }
    }
    const double best = static_cast<double>(escapes[static_cast<std::size_t>(measured)]);
    const double second = static_cast<double>(escapes[static_cast<std::size_t>(runnerUp)]);
    recordFigure(name, binName(expected) + " deg (Descartes " + formatted(caustic.scatteringDeg, "%.3f") + " deg)",
                 binName(measured) + " deg",
                 "bound: that bin; runner-up " + binName(runnerUp) + " is " +
                     formatted((best - second) / std::sqrt(best + second), "%.1f") + " sigma dimmer");
    EXPECT_EQ(measured, expected) << "brightest bin " << binName(measured) << " deg, expected " << binName(expected);
}

TEST(Rainbow, PrimaryBowIsAtDescartesMinimumDeviation) {
    expectBrightestBinAtTheCaustic("primary_rainbow", 1, kPrimaryWindow);
}

TEST(Rainbow, SecondaryBowIsAtDescartesMinimumDeviation) {
    expectBrightestBinAtTheCaustic("secondary_rainbow", 2, kSecondaryWindow);
}

// The escaped share per 0.1-degree bin by geometric optics, ray order by ray order with s and p tracked
// (tests/transport/SphereRayOptics.hpp, docs/validation.md "Ray optics of a sphere with s and p tracked"),
// for a beam of the sphere's radius.
std::vector<double> rayOrderShares(double n, double sigmaRadius) {
    constexpr int kOrders = 8;  // one by one; the rest summed
    std::vector<double> edges;
    for (int bin = 0; bin <= kBins; ++bin) edges.push_back(180.0 * bin / kBins);
    const testing::SphereRayOptics optics = testing::sphereRayOptics(n, sigmaRadius, edges, kOrders);
    std::vector<double> shares;
    for (const testing::PowerFraction& bin : optics.bins) shares.push_back(bin.intensity());
    return shares;
}

double sum(const std::vector<double>& values, const Window& window) {
    double total = 0.0;
    for (int bin = firstBin(window); bin < endBin(window); ++bin) total += values[static_cast<std::size_t>(bin)];
    return total;
}

double solidAngle(const Window& window) {
    return 2 * std::numbers::pi * (std::cos(radians(window.loDeg)) - std::cos(radians(window.hiDeg)));
}

TEST(Rainbow, AlexandersDarkBandIsDarkerThanBothSides) {
    const SphereScene scene = loadSphereScene("rainbow");
    const std::vector<double> reference = rayOrderShares(scene.relativeIndex(), scene.sigma * scene.radius);
    const TraceResult& run = validationRun("rainbow", kBins);
    const auto& counts = test::angular(run).escapes();
    std::vector<double> measured(counts.begin(), counts.end());
    const double photons = static_cast<double>(run.photons);

    const auto radiance = [](const std::vector<double>& shares, const Window& window) {
        return sum(shares, window) / solidAngle(window);
    };
    const double band = radiance(measured, kDarkBand) / photons;
    const double expectedBand = radiance(reference, kDarkBand);
    for (const auto& [name, side] : {std::pair{"dark_band_contrast_inside_primary", kInsidePrimary},
                                     std::pair{"dark_band_contrast_outside_secondary", kOutsideSecondary}}) {
        const double expected = radiance(reference, side) / expectedBand;
        const double contrast = radiance(measured, side) / photons / band;
        // The ratio of two counts of one multinomial run: relative variance 1/n1 + 1/n2.
        const double sigma = contrast * std::sqrt(1 / sum(measured, kDarkBand) + 1 / sum(measured, side));
        recordFigure(
            name, formatted(expected, "%.3f") + " (geometric optics)",
            formatted(contrast, "%.3f") + " +- " + formatted(sigma, "%.2g") + " (band " + formatted(band, "%.3g") +
                " /sr, side " + formatted(band * contrast, "%.3g") + " /sr)",
            "bound: >= " + formatted(kAlexanderContrast, "%g") + " and within " + formatted(kSigmas, "%g") + " sigma");
        EXPECT_GE(contrast, kAlexanderContrast) << name;
        EXPECT_NEAR(contrast, expected, kSigmas * sigma) << name;
    }
}

}  // namespace
}  // namespace dropscope::validation
