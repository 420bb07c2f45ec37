// The shares of photons a sphere reflects and absorbs against the literature (docs/validation.md,
// "Reflection by the outer surface" and "Absorption of a weakly absorbing sphere").
#include "ValidationRuns.hpp"

#include "optics/Fresnel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope::validation {
namespace {

// The often-quoted diffuse reflectance of a flat water surface. It has two figures and no stated
// index (the integral gives 0.06646 for n = 4/3): twice its rounding, a loose check of the integral.
constexpr double kWaterDiffuseReflectance = 0.066;
constexpr double kLiteratureTolerance = 0.001;
// Every escape from opaque-sphere.json must be an outer reflection: any photon refracted in has to
// cross at least this many absorption lengths (the shortest chord is 2a sqrt(1 - 1/n²)).
constexpr double kOpaqueChordLengths = 500.0;
// The weak-absorption limit is first order in σa; the next term lowers the absorbed share by about σa
// of itself (0.1% here), an allowance on top of the statistical bound.
constexpr double kNextOrderPerSigmaRadius = 1.0;

// ∫ R(θ) sin 2θ dθ over [0, π/2]: the reflectance of a flat surface under a uniform sky, from the
// Fresnel equations, by the midpoint rule (2e5 steps: error far below 1e-9).
double diffuseReflectance(double n1, double n2) {
    constexpr int kSteps = 200000;
    const double step = std::numbers::pi / 2 / kSteps;
    double total = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * step;
        total += fresnelReflectance(std::cos(theta), n1, n2).unpolarised() * std::sin(2 * theta) * step;
    }
    return total;
}

TEST(OuterReflection, DiffuseReflectanceOfWaterMatchesTheLiteratureValue) {
    const SphereScene scene = loadSphereScene("opaque-sphere");
    const double computed = diffuseReflectance(scene.n1, scene.n2);
    recordFigure("diffuse_reflectance_literature", formatted(kWaterDiffuseReflectance, "%.3f") + " (literature)",
                 formatted(computed, "%.5f") + " (Fresnel integral, n = " + formatted(scene.relativeIndex()) + ")",
                 "bound: +- " + formatted(kLiteratureTolerance, "%g"), false);
    EXPECT_NEAR(computed, kWaterDiffuseReflectance, kLiteratureTolerance);
}

TEST(OuterReflection, OpaqueSphereReflectsTheDiffuseReflectanceOfAFlatSurface) {
    const SphereScene scene = loadSphereScene("opaque-sphere");
    const double n = scene.relativeIndex();
    ASSERT_GT(scene.sigma * 2 * scene.radius * std::sqrt(1 - 1 / (n * n)), kOpaqueChordLengths);
    const double expected = diffuseReflectance(scene.n1, scene.n2);

    const TraceResult& run = validationRun("opaque-sphere", 180);
    const double photons = static_cast<double>(run.photons);
    const double measured = test::fraction(test::fates(run).escaped(), run);
    const double tolerance = kSigmas * binomialSigma(expected, photons);
    recordFigure("outer_reflection_share", formatted(expected, "%.5f") + " (diffuse reflectance)",
                 formatted(measured, "%.5f") + " +- " + formatted(binomialSigma(expected, photons), "%.2g"),
                 "bound: " + formatted(kSigmas, "%g") + " sigma = " + formatted(tolerance, "%.2g"));
    EXPECT_EQ(test::fates(run).lost(), 0U);
    EXPECT_NEAR(measured, expected, tolerance);
}

TEST(WeakAbsorption, SphereAbsorbsTheGeometricOpticsLimit) {
    // C_abs = σ V n² [1 − (1 − 1/n²)^{3/2}]: the mean chord over the disk, times the beam's area.
    const SphereScene scene = loadSphereScene("weak-absorption");
    const double n = scene.relativeIndex();
    const double expected = n * n * (1 - std::pow(1 - 1 / (n * n), 1.5));

    const TraceResult& run = validationRun("weak-absorption", 180);
    const double photons = static_cast<double>(run.photons);
    const double absorbed = test::fraction(test::fates(run).absorbed(), run);
    const double perShare = scene.beamArea / (scene.sigma * scene.volume);  // C_abs/(σV) per absorbed share
    const double measured = absorbed * perShare;
    const double sigma = binomialSigma(expected / perShare, photons) * perShare;
    const double tolerance = kSigmas * sigma + kNextOrderPerSigmaRadius * scene.sigma * scene.radius * expected;
    recordFigure("weak_absorption_factor", formatted(expected, "%.4f") + " (C_abs/(sigma V), weak-absorption limit)",
                 formatted(measured, "%.4f") + " +- " + formatted(sigma, "%.2g"),
                 "bound: " + formatted(kSigmas, "%g") + " sigma + next order = " + formatted(tolerance, "%.2g"));
    EXPECT_NEAR(measured, expected, tolerance);
}

}  // namespace
}  // namespace dropscope::validation
