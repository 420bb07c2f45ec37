// A glass slab (a box much wider than the beam) at normal incidence, against the closed form with
// multiple internal reflections: with R = ((n-1)/(n+1))^2 and single-pass transmission a = exp(-sigma d),
//   T = (1-R)^2 a / (1 - R^2 a^2),   R_slab = R + R (1-R)^2 a^2 / (1 - R^2 a^2),   A = 1 - T - R_slab.
#include "TransportFixtures.hpp"
#include "transport/TallyExpectations.hpp"

#include "transport/RayTree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace dropscope {
namespace {

using test::fraction;
using testing::monteCarloTolerance;
using testing::sceneFromJson;

constexpr double kIndex = 1.5;
constexpr double kThickness = 2.0;

struct SlabExpectation {
    double transmitted, reflected, absorbed;
};

SlabExpectation closedForm(double sigma) {
    const double r = std::pow((kIndex - 1) / (kIndex + 1), 2);
    const double a = std::exp(-sigma * kThickness);
    const double denominator = 1 - r * r * a * a;
    const double t = (1 - r) * (1 - r) * a / denominator;
    const double reflected = r + r * (1 - r) * (1 - r) * a * a / denominator;
    return {t, reflected, 1 - t - reflected};
}

Scene slab(double sigma, double index = kIndex) {
    return sceneFromJson(
        R"("air": {"n": 1}, "glass": {"n": )" + std::to_string(index) + R"(, "sigma": )" + std::to_string(sigma) + "}",
        R"({"type": "box", "min": [-50, -50, 0], "max": [50, 50, 2], "medium": "glass"})",
        R"({"type": "ray", "origin": [0.25, -0.5, -1], "direction": [0, 0, 1]})");
}

class SlabAtNormalIncidence : public ::testing::TestWithParam<double> {};

TEST_P(SlabAtNormalIncidence, MonteCarloMatchesTheClosedForm) {
    const double sigma = GetParam();
    const Scene scene = slab(sigma);
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 200000;
    const TraceResult result = test::traceStandard(optical, scene.sources, settings, 2);  // forward, backward
    const FateTally& tally = test::fates(result);
    const SlabExpectation expected = closedForm(sigma);
    const double n = static_cast<double>(tally.photons());

    EXPECT_EQ(tally.photons(), settings.photons);
    EXPECT_EQ(tally.escaped() + tally.absorbed() + tally.lost(), tally.photons());
    EXPECT_EQ(tally.lost(), 0U);
    EXPECT_EQ(tally.unscattered(), 0U);
    EXPECT_EQ(test::angular(result).escapes()[0] + test::angular(result).escapes()[1], tally.escaped());
    EXPECT_NEAR(fraction(test::angular(result).escapes()[0], result), expected.transmitted,
                monteCarloTolerance(expected.transmitted, n));
    EXPECT_NEAR(fraction(test::angular(result).escapes()[1], result), expected.reflected,
                monteCarloTolerance(expected.reflected, n));
    EXPECT_NEAR(fraction(tally.absorbed(), result), expected.absorbed, monteCarloTolerance(expected.absorbed, n));
    EXPECT_EQ(tally.events().tir, 0U);
    EXPECT_EQ(tally.events().absorb, tally.absorbed());
}

TEST_P(SlabAtNormalIncidence, RayTreeReproducesTheClosedFormToRounding) {
    const double sigma = GetParam();
    const Scene scene = slab(sigma);
    const OpticalScene optical(scene);
    RayTreeSettings settings;
    settings.minWeight = 1e-30;
    settings.maxDepth = 400;
    const RayTree tree = traceRayTree(optical, {scene.sources[0].origin, scene.sources[0].direction}, 1.0, settings);
    const std::vector<bool> leaves = tree.leaves();
    double forward = 0.0, backward = 0.0, truncated = 0.0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        if (!leaves[i]) continue;
        const Event& event = tree.nodes[i].event;
        if (event.type == EventType::Truncated) {
            truncated += event.weight;
        } else {
            ASSERT_EQ(event.type, EventType::Escape);
            (event.direction.z() > 0 ? forward : backward) += event.weight;
        }
    }
    const SlabExpectation expected = closedForm(sigma);
    constexpr double kSeriesRounding = 1e-14;       // a few ulps per term of a geometric series of ~40 terms
    EXPECT_LT(truncated, 10 * settings.minWeight);  // only the last few branches of the series are cut
    EXPECT_NEAR(forward, expected.transmitted, kSeriesRounding);
    EXPECT_NEAR(backward, expected.reflected, kSeriesRounding);
    EXPECT_NEAR(tree.absorbed, expected.absorbed, kSeriesRounding);
    EXPECT_NEAR(tree.leafWeight() + tree.absorbed, 1.0, kSeriesRounding);
}

INSTANTIATE_TEST_SUITE_P(ClearAndAbsorbing, SlabAtNormalIncidence, ::testing::Values(0.0, 0.05, 0.8));

TEST(BeerLambert, AnIndexMatchedSlabTransmitsExactlyExpMinusSigmaD) {
    // n equal on both sides: R = 0, so nothing but absorption acts.
    const double sigma = 0.6;
    const Scene scene = slab(sigma, 1.0);
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 100000;
    const TraceResult result = test::traceStandard(optical, scene.sources, settings);
    const double expected = std::exp(-sigma * kThickness);
    EXPECT_EQ(test::fates(result).events().reflect, 0U);
    EXPECT_NEAR(fraction(test::fates(result).escaped(), result), expected, monteCarloTolerance(expected, 1e5));

    const RayTree tree = traceRayTree(optical, {scene.sources[0].origin, scene.sources[0].direction}, 1.0, {});
    EXPECT_NEAR(tree.absorbed, 1.0 - expected, 4 * std::numeric_limits<double>::epsilon());  // one exp, one subtraction
}

TEST(BeerLambert, AbsorptionDistancesInAnAbsorbingAmbientAreExponential) {
    // No shapes: every photon is absorbed, at a distance with mean and standard deviation 1/sigma.
    const double sigma = 0.5;
    const Scene scene = sceneFromJson(R"("air": {"n": 1, "sigma": 0.5})", "",
                                      R"({"type": "ray", "origin": [1, 2, 3], "direction": [0, 0, 1]})");
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 20000;
    settings.paths = settings.photons;
    const TraceResult result = test::traceStandard(optical, scene.sources, settings);
    ASSERT_EQ(test::fates(result).absorbed(), settings.photons);
    ASSERT_EQ(result.paths.size(), settings.photons);
    double sum = 0.0;
    for (const PhotonPath& path : result.paths) {
        ASSERT_EQ(path.events.size(), 2U);
        EXPECT_EQ(path.events[0].type, EventType::Emit);
        EXPECT_EQ(path.events[1].type, EventType::Absorb);
        sum += (path.events[1].position - Point(1, 2, 3)).norm();
    }
    const double n = static_cast<double>(settings.photons);
    EXPECT_NEAR(sum / n, 1 / sigma, 5.0 / sigma / std::sqrt(n));
}

}  // namespace
}  // namespace dropscope
