// Plane detectors against closed forms (docs/validation.md, "Detectors and ray orders"): a point source's
// pixels against their solid angles, a glass slab's transmission with every internal reflection, and a ball
// lens's focus.
#include "DetectorRuns.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope::validation {
namespace {

// --- a point source and a plane

// 96 pixels of a 3 x 2 screen at distance 1, off the foot of the perpendicular by (0.5, -0.25), so that both
// the inverse square and the cosine vary across it (the corners are 62 degrees off the normal).
constexpr std::uint64_t kPointPhotons = 4'000'000;
const char* kPointScene = R"({"dropscope": 1, "unit": "mm",
  "sources": [{"type": "point", "origin": [0, 0, 0]}],
  "detectors": [{"type": "plane", "name": "screen", "center": [0.5, -0.25, 1], "normal": [0, 0, 1],
                 "up": [0, 1, 0], "size": [3, 2], "pixels": [12, 8]}]})";

// The solid angle of the rectangle [x0, x1] x [y0, y1] of a plane at distance d, with (x, y) measured from the
// foot of the perpendicular from the point: the corner sum of atan(xy / (d sqrt(d^2 + x^2 + y^2))).
double rectangleSolidAngle(double x0, double x1, double y0, double y1, double d) {
    const auto corner = [d](double x, double y) { return std::atan(x * y / (d * std::hypot(d, x, y))); };
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

TEST(PointSourcePlane, EachPixelsShareIsItsSolidAngleOverFourPi) {
    const Scene scene = parseScene(kPointScene, "point.json");
    const Detector& screen = scene.detectors.at(0);
    const TraceResult run = traceDetectors(scene, kPointPhotons);
    const ResultReport report = reportOf(run);
    const std::vector<double>& fraction = columnOf<double>(tableOf(report, "detector-screen"), "fraction");
    // The source's foot on the screen, in the screen's frame (u along x, v along y here).
    const PlaneFrame frame = planeFrame(screen);
    const Eigen::Vector3d toSource = Point::Zero() - screen.center;
    const double footU = toSource.dot(frame.u), footV = toSource.dot(frame.v);
    const double distance = std::abs(toSource.dot(frame.n));
    const double du = screen.size[0] / screen.pixels.nx, dv = screen.size[1] / screen.pixels.ny;
    const auto photons = static_cast<double>(run.photons);

    double chiSquare = 0.0, worstSigmas = 0.0, expectedTotal = 0.0, measuredTotal = 0.0;
    for (int iy = 0; iy < screen.pixels.ny; ++iy) {
        for (int ix = 0; ix < screen.pixels.nx; ++ix) {
            const auto [u, v] = planePixelCentre(screen, ix, iy);
            const double expected = rectangleSolidAngle(u - du / 2 - footU, u + du / 2 - footU, v - dv / 2 - footV,
                                                        v + dv / 2 - footV, distance) /
                                    (4 * std::numbers::pi);
            const double measured = fraction[screen.pixels.index(ix, iy)];
            const double sigma = binomialSigma(expected, photons);
            chiSquare += std::pow((measured - expected) / sigma, 2) * (1 - expected);  // multinomial: N p, not N p q
            worstSigmas = std::max(worstSigmas, std::abs(measured - expected) / sigma);
            expectedTotal += expected;
            measuredTotal += measured;
        }
    }
    // The photons that miss the screen are the multinomial's last cell.
    chiSquare += std::pow(measuredTotal - expectedTotal, 2) * photons / (1 - expectedTotal);
    // The chi-square of k = 96 pixels (k degrees of freedom, the outside cell closing the multinomial) has mean
    // k and standard deviation sqrt(2k): the bound is 5 of those above the mean.
    const double pixels = static_cast<double>(screen.pixels.count());
    const double chiSquareBound = pixels + kSigmas * std::sqrt(2 * pixels);
    const double totalSigma = binomialSigma(expectedTotal, photons);
    const std::string traced = ", " + formatted(photons, "%.3g") + " photons";
    recordFigure("point_plane_total_share", formatted(expectedTotal, "%.6f") + " (solid angle / 4 pi)",
                 formatted(measuredTotal, "%.6f") + " +- " + formatted(totalSigma, "%.2g"), "bound: 5 sigma" + traced,
                 false);
    recordFigure("point_plane_chi_square", formatted(pixels, "%.0f") + " (degrees of freedom)",
                 formatted(chiSquare, "%.1f") + ", worst pixel " + formatted(worstSigmas, "%.2f") + " sigma",
                 "bound: " + formatted(chiSquareBound, "%.1f") + ", each pixel 5 sigma" + traced, false);
    EXPECT_NEAR(measuredTotal, expectedTotal, kSigmas * totalSigma);
    EXPECT_LT(chiSquare, chiSquareBound);
    EXPECT_LT(worstSigmas, kSigmas);
}

// --- a glass slab at normal incidence

constexpr double kGlassIndex = 1.5;
constexpr double kSlabThickness = 2.0;
// Slab photons are cheap (two to four interfaces): 2e6 make one binomial sigma of T = 0.92 1.9e-4.
constexpr std::uint64_t kSlabPhotons = 2'000'000;

Scene slabScene(double sigma) {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "ambient": "air",
      "media": {"air": {"n": 1}, "glass": {"n": )" +
                          formatted(kGlassIndex) + R"(, "sigma": )" + formatted(sigma, "%.17g") + R"(}},
      "shapes": [{"type": "box", "min": [-50, -50, 0], "max": [50, 50, )" +
                          formatted(kSlabThickness) + R"(], "medium": "glass"}],
      "sources": [{"type": "ray", "origin": [0.25, -0.5, -1], "direction": [0, 0, 1]}],
      "detectors": [{"type": "plane", "name": "behind", "center": [0, 0, 3], "normal": [0, 0, 1],
                     "up": [0, 1, 0], "size": [10, 10], "pixels": [1, 1]}]})",
                      "slab.json");
}

TEST(SlabTransmission, APlaneBehindASlabSeesTheIncoherentSumOfEveryInternalReflection) {
    // Born and Wolf, Principles of Optics, on a plate's multiple reflections, summed in intensity:
    // T = (1 - R)^2 a / (1 - R^2 a^2), a = exp(-sigma d) the single pass; (1 - R) / (1 + R) when clear.
    const double r = std::pow((kGlassIndex - 1) / (kGlassIndex + 1), 2);
    for (const double sigma : {0.0, 0.2}) {
        SCOPED_TRACE(sigma);
        const double a = std::exp(-sigma * kSlabThickness);
        const double expected = (1 - r) * (1 - r) * a / (1 - r * r * a * a);
        if (sigma == 0.0) {
            EXPECT_NEAR(expected, (1 - r) / (1 + r), 1e-15);
        }
        const TraceResult run = traceDetectors(slabScene(sigma), kSlabPhotons);
        const ResultReport report = reportOf(run);
        const auto photons = static_cast<double>(run.photons);
        const double measured = static_cast<double>(summaryCount(report, {"detectors", "behind", "hits"})) / photons;
        const double sigmaT = binomialSigma(expected, photons);
        recordFigure("slab_transmission_sigma_" + formatted(sigma), formatted(expected, "%.6f"),
                     formatted(measured, "%.6f") + " +- " + formatted(sigmaT, "%.2g"),
                     "bound: 5 sigma, " + formatted(photons, "%.3g") + " photons", false);
        EXPECT_NEAR(measured, expected, kSigmas * sigmaT);
    }
}

// --- a ball lens

constexpr double kBallRadius = 1.0;
constexpr double kBeamRadius = 0.05;  // 0.05 R: paraxial
constexpr std::uint64_t kLensPhotons = 100'000;
// Screens at f + these offsets (scene units) from the sphere's centre. Geometric optics (a trace of this beam
// by hand, docs/validation.md) gives an RMS spot radius of 1.7e-5 at f, 6e-5 at f +- 0.002 and 1.2e-3 at
// f +- 0.05: spherical aberration moves the smallest spot towards the lens by about 0.0005, far less than 0.02.
constexpr double kScreenOffsets[] = {-0.05, -0.02, 0.0, 0.02, 0.05};
// At f +- 0.05 the defocused spot is the beam's disk scaled by 0.05 / f: RMS a |delta| / (f sqrt 2). Spherical
// aberration makes the two sides differ by 3 % (the trace by hand); the statistical error of an RMS over 9e4
// photons is 0.2 %: within 10 %.
constexpr double kDefocusTolerance = 0.10;

TEST(BallLens, TheSpotIsSmallestAtTheEffectiveFocalLength) {
    // Hecht, Optics, the ball lens: effective focal length f = nR / (2 (n - 1)) from the centre.
    const double f = kGlassIndex * kBallRadius / (2 * (kGlassIndex - 1));
    std::string screens;
    for (std::size_t k = 0; k < std::size(kScreenOffsets); ++k) {
        screens += std::string(screens.empty() ? "" : ", ") + R"({"type": "plane", "name": "screen)" +
                   std::to_string(k) + R"(", "center": [0, 0, )" + formatted(f + kScreenOffsets[k], "%.17g") +
                   R"(], "normal": [0, 0, 1], "up": [0, 1, 0], "size": [0.4, 0.4], "pixels": [40, 40], "record": )" +
                   std::to_string(kLensPhotons) + "}";
    }
    const Scene scene = parseScene(R"({"dropscope": 1, "unit": "mm", "ambient": "air",
      "media": {"air": {"n": 1}, "glass": {"n": )" +
                                       formatted(kGlassIndex) +
                                       R"(}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": )" +
                                       formatted(kBallRadius) + R"(, "medium": "glass"}],
      "sources": [{"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": )" +
                                       formatted(kBeamRadius) + R"(}],
      "detectors": [)" + screens + "]}",
                                   "ball-lens.json");
    const ResultReport report = reportOf(traceDetectors(scene, kLensPhotons));
    std::vector<double> rms;
    for (std::size_t k = 0; k < std::size(kScreenOffsets); ++k) {
        const double offset = kScreenOffsets[k];
        const ResultTable& hits = tableOf(report, "detector-screen" + std::to_string(k) + "-records");
        const auto& x = columnOf<double>(hits, "x");
        const auto& y = columnOf<double>(hits, "y");
        const auto& events = columnOf<std::uint64_t>(hits, "events");
        // Only the light straight through (p1: refracted in, refracted out); reflections go elsewhere.
        double sum = 0.0, count = 0.0;
        for (std::size_t hit = 0; hit < x.size(); ++hit) {
            if (events[hit] != 2) continue;
            sum += x[hit] * x[hit] + y[hit] * y[hit];
            count += 1.0;
        }
        ASSERT_GT(count, 0.9 * static_cast<double>(kLensPhotons));
        rms.push_back(std::sqrt(sum / count));
        const double paraxial = kBeamRadius * std::abs(offset) / (f * std::sqrt(2.0));
        recordFigure("ball_lens_rms_radius_at_f" + formatted(offset, "%+.2f"),
                     offset == 0.0 ? "the least" : formatted(paraxial, "%.3g") + " (defocused paraxial disk)",
                     formatted(rms.back(), "%.3g"), formatted(count, "%.0f") + " p1 photons", false);
        if (std::abs(offset) >= 0.05) {
            EXPECT_NEAR(rms.back(), paraxial, kDefocusTolerance * paraxial) << offset;
        }
    }
    const std::size_t atFocus = 2;
    for (std::size_t k = 0; k < rms.size(); ++k) {
        if (k != atFocus) {
            EXPECT_LT(rms[atFocus], rms[k]) << "screen at f" << kScreenOffsets[k];
        }
    }
}

}  // namespace
}  // namespace dropscope::validation
