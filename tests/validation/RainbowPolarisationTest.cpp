// The rainbows' polarisation in rainbow.json against ray optics with s and p tracked (tests/transport/
// SphereRayOptics.hpp), and what the unpolarised Fresnel model does to the light inside the primary bow
// (docs/validation.md, "The rainbow's polarisation" and "Water: what the unpolarised model gets wrong").
#include "ValidationRuns.hpp"

#include "transport/SphereRayOptics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace dropscope::validation {
namespace {

constexpr int kBins = 1800;             // 0.1 degree, as the rainbow test
constexpr int kOrders = kLastRayOrder;  // one by one in the reference (0 .. kOrders - 1); the rest summed

struct Band {
    const char* name;
    double loDeg;
    double hiDeg;
};

std::size_t binOf(double degrees) { return static_cast<std::size_t>(std::lround(degrees / 180.0 * kBins)); }

testing::SphereRayOptics reference(const SphereScene& scene) {
    std::vector<double> edges;
    for (int bin = 0; bin <= kBins; ++bin) edges.push_back(180.0 * bin / kBins);
    return testing::sphereRayOptics(scene.relativeIndex(), scene.sigma * scene.radius, edges, kOrders - 1);
}

// Shares of the photons escaping into the band: I and Q in the scattering-plane frame.
struct Measured {
    double intensity = 0.0;
    double q = 0.0;
};

Measured measured(const TraceResult& run, const Band& band) {
    const AngularTally::Columns columns = test::angular(run).columns();
    Measured sum;
    for (std::size_t bin = binOf(band.loDeg); bin < binOf(band.hiDeg); ++bin) {
        sum.intensity += columns.fraction[bin];
        if (!columns.stokesQ.empty()) sum.q += columns.stokesQ[bin];
    }
    return sum;
}

// The power of each ray order, the backscatter and g of the rainbow sphere: with s and p tracked, and what
// the unpolarised model would give (for the table of docs/validation.md).
void expectRayOrders(const TraceResult& run, const testing::SphereRayOptics& expected) {
    const test::RayOrderTally& tally = run.tallies.get<test::RayOrderTally>();
    const double n = static_cast<double>(run.photons);
    for (int order = 0; order <= kOrders; ++order) {
        const testing::PowerFraction& power =
            order < kOrders ? expected.orders[static_cast<std::size_t>(order)].total : expected.higherOrders.total;
        const double share = power.intensity();
        const double measured = test::fraction(tally.orders()[static_cast<std::size_t>(order)], run);
        const std::string name = order < kOrders ? "ray_order_" + std::to_string(order) : "ray_orders_above";
        recordFigure(name,
                     formatted(share, "%.6f") + " (s and p; unpolarised model " +
                         formatted(power.unpolarisedFresnel, "%.6f") + ")",
                     formatted(measured, "%.6f") + " +- " + formatted(binomialSigma(share, n), "%.2g"),
                     "bound: " + formatted(kSigmas, "%g") + " sigma");
        EXPECT_NEAR(measured, share, kSigmas * binomialSigma(share, n)) << name;
    }
    const double backscatter = test::fraction(tally.backscattered(), run);
    const double expectedBackscatter = expected.backscattered.intensity();
    recordFigure("backscatter_above_90_deg",
                 formatted(expectedBackscatter, "%.5f") + " (s and p; unpolarised model " +
                     formatted(expected.backscattered.unpolarisedFresnel, "%.5f") + ")",
                 formatted(backscatter, "%.5f") + " +- " + formatted(binomialSigma(expectedBackscatter, n), "%.2g"),
                 "bound: " + formatted(kSigmas, "%g") + " sigma");
    EXPECT_NEAR(backscatter, expectedBackscatter, kSigmas * binomialSigma(expectedBackscatter, n));
    recordFigure("asymmetry_parameter_g",
                 formatted(expected.asymmetry, "%.5f") + " (s and p; unpolarised model " +
                     formatted(expected.asymmetryUnpolarisedFresnel, "%.5f") + ")",
                 formatted(tally.asymmetry(), "%.5f") + " +- " + formatted(tally.asymmetrySigma(), "%.2g"),
                 "bound: " + formatted(kSigmas, "%g") + " sigma");
    EXPECT_NEAR(tally.asymmetry(), expected.asymmetry, kSigmas * tally.asymmetrySigma());
}

TEST(RainbowPolarisation, TheRainbowSphereIsRayOpticsWithSAndPTracked) {
    // The ray orders, g and the backscatter; then -Q/I (-P12/P11, > 0 for light polarised across the
    // scattering plane, i.e. along the bow) in 1-degree bands on the bright side of each bow. Each photon's
    // |Q| <= I = 1, so Q's standard deviation over n photons is at most sqrt(share / n); -Q/I's by the
    // ratio's first-order error.
    const SphereScene scene = loadSphereScene("rainbow");
    const testing::SphereRayOptics expected = reference(scene);
    const TraceResult& run = validationRun("rainbow", kBins);
    expectRayOrders(run, expected);
    const double n = static_cast<double>(run.photons);
    for (const Band& band :
         {Band{"primary_rainbow_polarisation", 138.0, 139.0}, Band{"secondary_rainbow_polarisation", 128.0, 129.0}}) {
        const testing::PowerFraction power = testing::bandPower(expected, expected.bins, band.loDeg, band.hiDeg);
        const Measured got = measured(run, band);
        const double ratio = -got.q / got.intensity;
        const double sigma =
            (std::sqrt(got.intensity / n) + std::abs(ratio) * binomialSigma(got.intensity, n)) / got.intensity;
        recordFigure(band.name,
                     formatted(power.degreeOfPolarisation(), "%.4f") + " (-P12/P11, " + formatted(band.loDeg, "%g") +
                         "-" + formatted(band.hiDeg, "%g") + " deg, ray optics with s and p)",
                     formatted(ratio, "%.4f") + " +- " + formatted(sigma, "%.2g"),
                     "bound: " + formatted(kSigmas, "%g") + " sigma");
        EXPECT_NEAR(ratio, power.degreeOfPolarisation(), kSigmas * sigma) << band.name;
    }
}

TEST(RainbowPolarisation, UnpolarisedFresnelPutsTooMuchLightInsideThePrimaryBow) {
    // Between 139 and 150 degrees (orders 1 and 2 inside the primary bow) the unpolarised model's power is
    // ray optics' 1.086 times that of s and p tracked. Measured as the ratio of two independent runs'
    // shares: relative variance (1 - p1)/(n p1) + (1 - p2)/(n p2).
    const SphereScene scene = loadSphereScene("rainbow");
    const testing::SphereRayOptics expected = reference(scene);
    const Band band{"unpolarised_over_polarised_139_150", 139.0, 150.0};
    const testing::PowerFraction power = testing::bandPower(expected, expected.bins, band.loDeg, band.hiDeg);
    const double expectedRatio = power.unpolarisedFresnel / power.intensity();
    const double polarised = measured(validationRun("rainbow", kBins), band).intensity;
    const double unpolarised = measured(validationRun("rainbow", kBins, PolarisationModel::None), band).intensity;
    const double n = static_cast<double>(validationPhotons());
    const double ratio = unpolarised / polarised;
    const double sigma = ratio * std::sqrt((1 - polarised) / (n * polarised) + (1 - unpolarised) / (n * unpolarised));
    recordFigure(band.name, formatted(expectedRatio, "%.4f") + " (ray optics, s and p against unpolarised Fresnel)",
                 formatted(ratio, "%.4f") + " +- " + formatted(sigma, "%.2g") + " (--polarisation none / stokes)",
                 "bound: " + formatted(kSigmas, "%g") + " sigma");
    EXPECT_NEAR(ratio, expectedRatio, kSigmas * sigma);
    EXPECT_GT(ratio, 1.05);  // the bias the polarised tracer removes
}

}  // namespace
}  // namespace dropscope::validation
