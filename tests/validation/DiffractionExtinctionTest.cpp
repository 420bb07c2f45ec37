// The extinction paradox in the tracer (docs/validation.md, "Diffraction"): the ballistic (unscattered)
// transmission of a dilute cloud of water droplets through the cloud, without diffraction and with
// --diffraction fraunhofer. Without, a droplet removes the photons that hit its outline (pi a^2); with, also those
// through its halo's ring (2 pi a^2 in all). Checked against the exact uncovered share of the beam for the cloud
// drawn (a 2D quadrature over the droplets' disks, independent of the tracer), and against Beer-Lambert.
#include "DetectorRuns.hpp"

#include "geometry/Sphere.hpp"
#include "tally/FateTally.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <unordered_map>

namespace dropscope::validation {
namespace {

constexpr double kBeamRadius = 4.0;
constexpr double kDropletRadius = 0.1;  // x = 2 pi a / lambda = 1181 at 532 nm
constexpr int kDroplets = 1000;
constexpr std::uint64_t kPhotons = 200'000;

Scene diluteCloud() {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
      "generators": [{"type": "droplet_cloud", "region": {"min": [-5, -5, -5], "max": [5, 5, 5]}, "count": )" +
                          std::to_string(kDroplets) + R"(,
        "radius": {"distribution": "fixed", "value": 0.1}, "medium": "water", "seed": 3}],
      "sources": [{"type": "beam", "origin": [0, 0, -10], "direction": [0, 0, 1], "radius": 4}]})",
                      "dilute-cloud.json");
}

double unscatteredShare(const Scene& scene, DiffractionModel diffraction) {
    TraceSettings settings;
    settings.photons = kPhotons;
    settings.seed = 1;
    settings.transport.polarisation = PolarisationModel::None;
    settings.transport.diffraction = diffraction;
    const TraceResult run = runTrace(OpticalScene(scene, diffraction != DiffractionModel::None), scene.sources,
                                     settings, standardTallies(kDetectorRunBins, PolarisationModel::None));
    return static_cast<double>(run.tallies.get<FateTally>().unscattered()) / static_cast<double>(run.photons);
}

// The share of the beam's disk (seen along z) outside every droplet's disk scaled by `scale`: the midpoint rule on
// a 1600 x 1600 grid over the beam, the disks found through 0.5 mm buckets. Its error, the disks' rims resolved
// to 0.005 mm, is below 1e-3 of the beam (measured: halving the step moves it by less than 2e-4).
double uncoveredShare(const Scene& scene, double scale) {
    constexpr int kGrid = 1600;
    constexpr double kBucket = 0.5;
    const auto key = [](long i, long j) { return i * 100003L + j; };
    std::unordered_map<long, std::vector<Eigen::Vector2d>> buckets;
    const double reach = scale * kDropletRadius;
    for (const auto& shape : scene.shapes) {
        const auto& sphere = dynamic_cast<const Sphere&>(*shape);
        const Eigen::Vector2d centre(sphere.center().x(), sphere.center().y());
        for (long i = std::lround(std::floor((centre.x() - reach) / kBucket));
             i <= std::lround(std::floor((centre.x() + reach) / kBucket)); ++i) {
            for (long j = std::lround(std::floor((centre.y() - reach) / kBucket));
                 j <= std::lround(std::floor((centre.y() + reach) / kBucket)); ++j) {
                buckets[key(i, j)].push_back(centre);
            }
        }
    }
    long inside = 0;
    long uncovered = 0;
    const double step = 2.0 * kBeamRadius / kGrid;
    for (int a = 0; a < kGrid; ++a) {
        for (int b = 0; b < kGrid; ++b) {
            const Eigen::Vector2d p(-kBeamRadius + (a + 0.5) * step, -kBeamRadius + (b + 0.5) * step);
            if (p.norm() > kBeamRadius) continue;
            ++inside;
            const auto found =
                buckets.find(key(std::lround(std::floor(p.x() / kBucket)), std::lround(std::floor(p.y() / kBucket))));
            bool covered = false;
            if (found != buckets.end()) {
                for (const Eigen::Vector2d& centre : found->second) covered = covered || (p - centre).norm() < reach;
            }
            uncovered += !covered;
        }
    }
    return static_cast<double>(uncovered) / static_cast<double>(inside);
}

TEST(DiffractionExtinction, ADiluteCloudsBallisticTransmissionFallsByTwiceTheGeometricCrossSection) {
    const Scene scene = diluteCloud();
    ASSERT_EQ(scene.shapes.size(), static_cast<std::size_t>(kDroplets));
    const double rayOptics = unscatteredShare(scene, DiffractionModel::None);
    const double diffraction = unscatteredShare(scene, DiffractionModel::Fraunhofer);
    const double photons = static_cast<double>(kPhotons);
    // The cloud drawn: the beam's share outside every outline, and outside every halo (radius sqrt 2 a).
    const double outlines = uncoveredShare(scene, 1.0);
    const double haloes = uncoveredShare(scene, std::sqrt(2.0));
    constexpr double kQuadrature = 1e-3;
    recordFigure("ballistic_transmission_ray_optics", formatted(outlines, "%.4f") + " (beam outside every outline)",
                 formatted(rayOptics, "%.4f"), "5 sigma + 1e-3", false);
    recordFigure("ballistic_transmission_diffraction", formatted(haloes, "%.4f") + " (beam outside every halo)",
                 formatted(diffraction, "%.4f"), "5 sigma + 1e-3", false);
    EXPECT_NEAR(rayOptics, outlines, kSigmas * binomialSigma(outlines, photons) + kQuadrature);
    EXPECT_NEAR(diffraction, haloes, kSigmas * binomialSigma(haloes, photons) + kQuadrature);

    // Beer-Lambert: centres uniform in the region shrunk by a (9.8 mm a side), so along the beam the optical depth
    // is N sigma / 9.8^2 with sigma = pi a^2 or 2 pi a^2. The cloud drawn departs from the mean of all clouds by
    // about 2 % in -ln T (its ~500 droplets in the beam fluctuate), hence 10 %.
    const double geometric = std::numbers::pi * kDropletRadius * kDropletRadius;
    const double side = 10.0 - 2.0 * kDropletRadius;
    const double perCrossSection = kDroplets / (side * side);
    const double sigmaRayOptics = -std::log(rayOptics) / perCrossSection / geometric;
    const double sigmaDiffraction = -std::log(diffraction) / perCrossSection / geometric;
    recordFigure("extinction_per_droplet_ray_optics", "1 pi a^2", formatted(sigmaRayOptics, "%.3f") + " pi a^2",
                 "10 % (the cloud drawn)", false);
    recordFigure("extinction_per_droplet_diffraction", "2 pi a^2", formatted(sigmaDiffraction, "%.3f") + " pi a^2",
                 "10 % (the cloud drawn)", false);
    EXPECT_NEAR(sigmaRayOptics, 1.0, 0.1);
    EXPECT_NEAR(sigmaDiffraction, 2.0, 0.2);
    EXPECT_NEAR(std::log(diffraction) / std::log(rayOptics), 2.0, 0.1);
}

}  // namespace
}  // namespace dropscope::validation
