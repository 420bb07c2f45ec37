// Ray orders (docs/validation.md, "Detectors and ray orders"): the columns of angular_orders add up to the
// escapes, a water sphere's p0, p1 and p2 shares are the Fresnel integrals over the impact parameter (with the
// unpolarised reflectance and with s and p apart), and a cloud's multiple scattering grows with its depth.
#include "DetectorRuns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope::validation {
namespace {

constexpr double kWaterIndex = 1.333;
// One binomial sigma of p2 (0.04) among 4e6 photons is 1e-4: the two polarisation models' p2 differ by 33 of it.
constexpr std::uint64_t kSpherePhotons = 4'000'000;
// Composite Simpson steps in theta_i over [0, pi/2]: the integrands are smooth in theta_i (R is analytic there,
// with no total reflection inside a sphere), so the error, O(h^4), is below 1e-12.
constexpr int kSimpsonSteps = 20'000;

// The Fresnel reflectances of s and p light from index 1 into n at incidence thetaI (written here again, apart
// from engine/optics). Inside the sphere the angle is theta_t and the reflectances are the same (Stokes).
std::pair<double, double> fresnelSP(double thetaI, double n) {
    const double cosI = std::cos(thetaI);
    const double sinT = std::sin(thetaI) / n;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double rs = (cosI - n * cosT) / (cosI + n * cosT);
    const double rp = (n * cosI - cosT) / (n * cosI + cosT);
    return {rs * rs, rp * rp};
}

// The share of a beam as wide as the sphere that leaves with ray order p (van de Hulst 1957, ch. 12): a ray
// of impact parameter b = sin(theta_i) has weight 2b db = sin(2 theta_i) d theta_i, and leaves with order p
// carrying R (p = 0) or (1 - R)^2 R^(p-1). `polarised`: s and p apart, each with half the power; otherwise the
// unpolarised R at every interface, as the tracer's PolarisationModel::None does.
double orderShare(int p, double n, bool polarised) {
    const auto orderPower = [p](double r) { return p == 0 ? r : (1 - r) * (1 - r) * std::pow(r, p - 1); };
    const auto integrand = [&](double thetaI) {
        const auto [rs, rp] = fresnelSP(thetaI, n);
        const double power = polarised ? 0.5 * (orderPower(rs) + orderPower(rp)) : orderPower(0.5 * (rs + rp));
        return power * std::sin(2 * thetaI);
    };
    const double h = std::numbers::pi / 2 / kSimpsonSteps;
    double sum = integrand(0.0) + integrand(std::numbers::pi / 2);
    for (int k = 1; k < kSimpsonSteps; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * integrand(k * h);
    return sum * h / 3.0;
}

Scene sphereScene() {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": )" +
                          formatted(kWaterIndex) + R"(}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
      "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1}]})",
                      "sphere.json");
}

std::uint64_t columnTotal(const std::vector<std::uint64_t>& column) {
    std::uint64_t total = 0;
    for (const std::uint64_t count : column) total += count;
    return total;
}

// The columns of angular_orders add up to single_scattering, and single + multiple + unscattered to the escapes,
// count for count.
void expectOrdersAddUp(const TraceResult& run) {
    const OrderTally& orders = run.tallies.get<OrderTally>();
    std::uint64_t columns = 0;
    for (std::size_t p = 0; p < OrderTally::kOrderColumns; ++p) columns += columnTotal(orders.order(p));
    EXPECT_EQ(columns, orders.singleTotal());
    EXPECT_EQ(orders.singleTotal() + orders.multipleTotal() + test::fates(run).unscattered(),
              test::fates(run).escaped());
    const SummaryValue* single = reportOf(run).find({"single_scattering"});
    ASSERT_NE(single, nullptr);
    EXPECT_EQ(std::get<double>(*single),
              static_cast<double>(orders.singleTotal()) / static_cast<double>(orders.photons()));
}

TEST(RayOrderShares, AWaterSpheresOrdersAreTheFresnelIntegralsOverTheImpactParameter) {
    const Scene scene = sphereScene();
    for (const PolarisationModel model : {PolarisationModel::None, PolarisationModel::Stokes}) {
        const bool polarised = model == PolarisationModel::Stokes;
        const std::string name(polarisationModelName(model));
        SCOPED_TRACE(name);
        const TraceResult run = traceDetectors(scene, kSpherePhotons, model);
        expectOrdersAddUp(run);
        EXPECT_EQ(run.tallies.get<OrderTally>().multipleTotal(), 0U);
        const auto photons = static_cast<double>(run.photons);
        for (int p = 0; p <= 2; ++p) {
            const double expected = orderShare(p, kWaterIndex, polarised);
            const auto& column = run.tallies.get<OrderTally>().order(static_cast<std::size_t>(p));
            const double measured = static_cast<double>(columnTotal(column)) / photons;
            const double sigma = binomialSigma(expected, photons);
            recordFigure("order_p" + std::to_string(p) + "_share_" + name, formatted(expected, "%.6f"),
                         formatted(measured, "%.6f") + " +- " + formatted(sigma, "%.2g"),
                         "bound: 5 sigma, " + formatted(photons, "%.3g") + " photons", false);
            EXPECT_NEAR(measured, expected, kSigmas * sigma) << "p" << p;
        }
    }
}

// Clouds of one droplet size (radius 0.1) in a 10 mm cube, ever more droplets: the mean optical depth along the
// beam, count x pi r^2 x 10 mm / 1000 mm^3, is 0.16, 0.47 and 1.4.
constexpr int kCloudCounts[] = {500, 1500, 4500};
// The shares are 1e-2 to 1e-1: one binomial sigma of 2e5 photons is 2e-4 to 7e-4.
constexpr std::uint64_t kCloudPhotons = 200'000;

Scene cloudScene(int droplets) {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": )" +
                          formatted(kWaterIndex) + R"(}},
      "generators": [{"type": "droplet_cloud", "region": {"min": [-5, -5, -5], "max": [5, 5, 5]}, "count": )" +
                          std::to_string(droplets) + R"(,
        "radius": {"distribution": "fixed", "value": 0.1}, "medium": "water", "seed": 7}],
      "sources": [{"type": "beam", "origin": [0, 0, -10], "direction": [0, 0, 1], "radius": 4}]})",
                      "cloud.json");
}

TEST(RayOrderShares, ACloudsMultipleScatteringGrowsWithItsOpticalDepth) {
    std::vector<double> shares, sigmas;
    for (const int droplets : kCloudCounts) {
        SCOPED_TRACE(droplets);
        const TraceResult run = traceDetectors(cloudScene(droplets), kCloudPhotons);
        expectOrdersAddUp(run);
        const auto photons = static_cast<double>(run.photons);
        shares.push_back(static_cast<double>(run.tallies.get<OrderTally>().multipleTotal()) / photons);
        sigmas.push_back(binomialSigma(shares.back(), photons));
    }
    for (std::size_t k = 1; k < shares.size(); ++k) {
        const double step = shares[k] - shares[k - 1];
        const double sigma = std::hypot(sigmas[k], sigmas[k - 1]);
        recordFigure("cloud_multiple_scattering_" + std::to_string(kCloudCounts[k - 1]) + "_to_" +
                         std::to_string(kCloudCounts[k]),
                     "an increase of more than 5 sigma",
                     formatted(shares[k - 1], "%.4f") + " -> " + formatted(shares[k], "%.4f") + " (" +
                         formatted(step / sigma, "%.0f") + " sigma)",
                     "2e5 photons each", false);
        EXPECT_GT(step, kSigmas * sigma);
    }
}

}  // namespace
}  // namespace dropscope::validation
