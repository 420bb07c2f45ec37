// The far field of one water sphere (docs/validation.md, "Detectors and ray orders"): a camera that sees the
// whole sky sees every escape and, ring by ring, what angular.csv counts; a camera looking away from the
// source sees the primary bow at Descartes' angle from the antisolar point.
#include "Descartes.hpp"
#include "DetectorRuns.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope::validation {
namespace {

constexpr double kWaterIndex = 1.333;
// 4e6 photons: the bow's 0.25-degree ring holds about 4e3 of them, 30 sigma brighter than the ring outside it.
constexpr std::uint64_t kSkyPhotons = 4'000'000;
// "sky": equal-area over 360 degrees, looking back at the source (look = -beam direction), so a pixel's
// theta_deg is the scattering angle of the photons it sees (they escape along d, seen from -d).
// "bow": equidistant over 120 degrees, 0.25-degree pixels, looking along the beam at the antisolar point.
constexpr int kSkyPixels = 360;
constexpr int kBowPixels = 480;
constexpr double kBowFovDeg = 120.0;
// Rings of the sky compared with angular.csv, and of the bow searched for its peak.
constexpr double kSkyRingDeg = 10.0;
constexpr double kBowRingDeg = 0.25;
constexpr double kBowSearchFromDeg = 35.0, kBowSearchToDeg = 50.0;
// The peak ring's centre must be within this of Descartes' angle: two rings, which holds the singularity's ring
// whichever side of a ring edge it falls, and the rings' aliasing on 0.25-degree pixels.
constexpr double kBowToleranceDeg = 0.5;

Scene skyScene() {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": )" +
                          formatted(kWaterIndex) + R"(}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
      "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1}],
      "detectors": [
        {"type": "far_field", "name": "sky", "look": [0, 0, -1], "up": [0, 1, 0], "projection": "equal_area",
         "fov_deg": 360, "pixels": [)" +
                          std::to_string(kSkyPixels) + ", " + std::to_string(kSkyPixels) + R"(]},
        {"type": "far_field", "name": "bow", "look": [0, 0, 1], "up": [0, 1, 0], "projection": "equidistant",
         "fov_deg": )" + formatted(kBowFovDeg) +
                          R"(, "pixels": [)" + std::to_string(kBowPixels) + ", " + std::to_string(kBowPixels) + "]}]}",
                      "sky.json");
}

const TraceResult& skyRun() {
    static const TraceResult run = traceDetectors(skyScene(), kSkyPhotons);
    return run;
}

// The range of theta (degrees) over pixel (ix, iy) of an equal-area image of 360 degrees (r = 2 sin(theta/2),
// image half-width 2): theta is monotonic in r, so it spans theta(nearest point) to theta(farthest corner).
std::pair<double, double> equalAreaPixelThetaDeg(int ix, int iy, int pixels) {
    const double size = 4.0 / pixels;
    const double x0 = (ix - pixels / 2.0) * size, x1 = x0 + size;
    const double y0 = (iy - pixels / 2.0) * size, y1 = y0 + size;
    const auto nearest = [](double lo, double hi) { return std::max({0.0, lo, -hi}); };
    const double rNear = std::hypot(nearest(x0, x1), nearest(y0, y1));
    const double rFar = std::hypot(std::max(std::abs(x0), std::abs(x1)), std::max(std::abs(y0), std::abs(y1)));
    const auto theta = [](double r) { return 2.0 * std::asin(std::min(r / 2.0, 1.0)) * 180.0 / std::numbers::pi; };
    return {theta(rNear), theta(rFar)};
}

TEST(FarField, AWholeSkyCameraSeesEveryEscape) {
    const TraceResult& run = skyRun();
    const ResultReport report = reportOf(run);
    const std::uint64_t escaped = test::fates(run).escaped();
    const std::uint64_t seen = summaryCount(report, {"detectors", "sky", "hits"});
    recordFigure("far_field_sky_hits", std::to_string(escaped) + " (escapes)", std::to_string(seen), "exact", false);
    EXPECT_EQ(seen, escaped);
    EXPECT_EQ(test::fates(run).lost(), 0U);
}

TEST(FarField, RingsOfTheSkyAgreeWithTheAngularTallyWithinTheirPixelation) {
    // Both tallies count the same photons of one run, so they differ only by the photons of pixels that straddle
    // a ring's edge (the sky bins a pixel by its centre): at most the fraction those pixels hold.
    const TraceResult& run = skyRun();
    const ResultReport report = reportOf(run);
    const ResultTable& sky = tableOf(report, "detector-sky");
    const auto& theta = columnOf<double>(sky, "theta_deg");
    const auto& fraction = columnOf<double>(sky, "fraction");
    const AngularTally::Columns angular = test::angular(run).columns();
    const int rings = static_cast<int>(180.0 / kSkyRingDeg);
    std::vector<double> fromSky(rings, 0.0), fromAngular(rings, 0.0), straddling(rings, 0.0);
    for (int iy = 0; iy < kSkyPixels; ++iy) {
        for (int ix = 0; ix < kSkyPixels; ++ix) {
            const std::size_t pixel = static_cast<std::size_t>(iy) * kSkyPixels + static_cast<std::size_t>(ix);
            // A pixel whose centre is beyond the projection's domain still sees the directions of its part within
            // it; its theta_deg is the edge's, 180 degrees (a pixel wholly beyond has none and sees nothing).
            const auto [lo, hi] = equalAreaPixelThetaDeg(ix, iy, kSkyPixels);
            const double centre = std::isfinite(theta[pixel]) ? theta[pixel] : (lo + hi) / 2.0;
            const int ring = std::min(static_cast<int>(centre / kSkyRingDeg), rings - 1);
            fromSky[static_cast<std::size_t>(ring)] += fraction[pixel];
            for (int k = std::max(0, static_cast<int>(lo / kSkyRingDeg));
                 k <= std::min(rings - 1, static_cast<int>(hi / kSkyRingDeg)); ++k) {
                if (lo < k * kSkyRingDeg || hi > (k + 1) * kSkyRingDeg)
                    straddling[static_cast<std::size_t>(k)] += fraction[pixel];
            }
        }
    }
    for (std::size_t bin = 0; bin < angular.fraction.size(); ++bin)
        fromAngular[static_cast<std::size_t>(angular.lower[bin] / kSkyRingDeg)] += angular.fraction[bin];
    for (int k = 0; k < rings; ++k) {
        const auto ring = static_cast<std::size_t>(k);
        recordFigure("far_field_ring_" + formatted(k * kSkyRingDeg, "%.0f") + "_deg",
                     formatted(fromAngular[ring], "%.6f") + " (angular.csv)", formatted(fromSky[ring], "%.6f"),
                     "pixelation bound " + formatted(straddling[ring], "%.2g") + ", 4e6 photons", false);
        EXPECT_LE(std::abs(fromSky[ring] - fromAngular[ring]), straddling[ring]) << "ring " << k;
    }
}

TEST(FarField, ThePrimaryBowIsAtDescartesAngleFromTheAntisolarPoint) {
    const double expected = 180.0 - descartes(kWaterIndex, 1).scatteringDeg;
    const Scene scene = skyScene();
    const Detector& bow = scene.detectors.at(1);
    const FarFieldCamera camera(bow);
    const ResultReport report = reportOf(skyRun());
    const ResultTable& table = tableOf(report, "detector-bow");
    const auto& theta = columnOf<double>(table, "theta_deg");
    const auto& fraction = columnOf<double>(table, "fraction");
    // The radiance of each ring about the antisolar point: its fraction over its solid angle.
    const auto rings = static_cast<std::size_t>(kBowFovDeg / 2.0 * std::numbers::sqrt2 / kBowRingDeg) + 1;
    std::vector<double> power(rings, 0.0), solidAngle(rings, 0.0);
    for (int iy = 0; iy < kBowPixels; ++iy) {
        for (int ix = 0; ix < kBowPixels; ++ix) {
            const std::size_t pixel = bow.pixels.index(ix, iy);
            if (!std::isfinite(theta[pixel])) continue;
            const auto ring = static_cast<std::size_t>(theta[pixel] / kBowRingDeg);
            power[ring] += fraction[pixel];
            solidAngle[ring] += camera.pixelSolidAngle(ix, iy);
        }
    }
    std::size_t peak = static_cast<std::size_t>(kBowSearchFromDeg / kBowRingDeg);
    for (auto ring = peak; ring < static_cast<std::size_t>(kBowSearchToDeg / kBowRingDeg); ++ring) {
        if (power[ring] / solidAngle[ring] > power[peak] / solidAngle[peak]) peak = ring;
    }
    const double measured = (static_cast<double>(peak) + 0.5) * kBowRingDeg;
    recordFigure("far_field_primary_bow_deg", formatted(expected, "%.3f") + " (Descartes, n = 1.333)",
                 formatted(measured, "%.3f") + " (brightest 0.25-degree ring's centre)",
                 "bound: " + formatted(kBowToleranceDeg) + " deg, 4e6 photons", false);
    EXPECT_NEAR(measured, expected, kBowToleranceDeg);
}

}  // namespace
}  // namespace dropscope::validation
