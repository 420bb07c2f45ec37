#include "TransportFixtures.hpp"
#include "transport/TallyExpectations.hpp"

#include "transport/RayTree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

using test::fraction;
using testing::monteCarloTolerance;

constexpr double kWeightRounding = 1e-13;  // sums of a few thousand products of weights in [0, 1]

Scene defaultScene() { return loadScene(DROPSCOPE_SOURCE_DIR "/assets/scenes/default.json"); }

// A pencil into the glass cell of the default scene, off-centre through the drop inside it.
const Ray kIntoTheCell{Point(0.3, -0.4, -8), Direction(0.02, 0.01, 1)};

TEST(RayTree, LeafWeightsPlusAbsorptionAddUpToTheInputWeight) {
    const OpticalScene optical(defaultScene());
    for (double weight : {1.0, 0.25}) {
        const RayTree tree = traceRayTree(optical, kIntoTheCell, weight, {});
        EXPECT_GT(tree.nodes.size(), 20U);
        EXPECT_GT(tree.absorbed, 0.0);
        EXPECT_NEAR(tree.leafWeight() + tree.absorbed, weight, kWeightRounding);
        EXPECT_EQ(tree.nodes[0].event.type, EventType::Emit);
        EXPECT_EQ(tree.nodes[0].parent, -1);
        for (std::size_t i = 1; i < tree.nodes.size(); ++i) {
            const RayTreeNode& node = tree.nodes[i];
            ASSERT_GE(node.parent, 0);
            ASSERT_LT(static_cast<std::size_t>(node.parent), i);  // parents come first
            // A branch never gains weight.
            EXPECT_LE(node.event.weight, tree.nodes[static_cast<std::size_t>(node.parent)].event.weight);
        }
    }
}

TEST(RayTree, StrongAbsorptionStillBalancesTheWeights) {
    // exp(-sigma s) underflows to 0 inside this drop: the branch ends in an absorb leaf of weight 0.
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "ink": {"n": 1.5, "sigma": 1000})",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "ink"})", "");
    const OpticalScene optical(scene);
    for (const Ray& ray : {Ray{Point(0.2, 0, -3), Direction(0, 0, 1)}, Ray{Point(0.2, 0, 0), Direction(0, 0, 1)}}) {
        const RayTree tree = traceRayTree(optical, ray, 1.0, {});
        EXPECT_NEAR(tree.leafWeight() + tree.absorbed, 1.0, kWeightRounding);
        EXPECT_EQ(tree.nodes.back().event.type, EventType::Absorb);
    }
}

TEST(RayTree, BranchesEndAtTheMinimumWeightOrTheMaximumDepth) {
    const OpticalScene optical(defaultScene());
    RayTreeSettings shallow;
    shallow.maxDepth = 3;
    shallow.minWeight = 0.0;
    const RayTree tree = traceRayTree(optical, kIntoTheCell, 1.0, shallow);
    const std::vector<bool> leaves = tree.leaves();
    int truncated = 0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        EXPECT_LE(tree.nodes[i].depth, 3);
        if (tree.nodes[i].event.type == EventType::Truncated) {
            EXPECT_TRUE(leaves[i]);
            EXPECT_EQ(tree.nodes[i].depth, 3);
            ++truncated;
        }
    }
    EXPECT_GE(truncated, 1);
    EXPECT_NEAR(tree.leafWeight() + tree.absorbed, 1.0, kWeightRounding);

    RayTreeSettings light;
    light.minWeight = 0.01;
    for (const RayTreeNode& node : traceRayTree(optical, kIntoTheCell, 1.0, light).nodes) {
        // Light branches end; so do heavy ones trapped by total internal reflection in the glass cell.
        if (node.event.type == EventType::Truncated) {
            EXPECT_TRUE(node.event.weight < 0.01 || node.depth == light.maxDepth);
        }
    }
}

// The Stokes vector of light escaping along k, in the scattering-plane frame of emission direction k0
// (what the angular tally sums; the tree's leaves carry their own frames).
StokesVector inScatteringPlane(const Polarisation& light, const Direction& k, const Direction& k0) {
    const Eigen::Vector3d inPlane = k0.vector() - k0.dot(k.vector()) * k.vector();
    return inPlane.norm() < 1e-9 ? light.stokes : stokesInFrame(light, k, inPlane.normalized());
}

TEST(RayTree, IsTheExpectationOfTheMonteCarloPhoton) {
    // The same pencil, linearly polarised, traced as 2e5 analog photons: the share escaping into each
    // 10-degree bin, the Stokes parameters Q, U, V escaping there and the share absorbed are the ray tree's
    // leaves (the Mueller products along each branch), within Monte Carlo noise. So choosing a branch with
    // the probability of its power and renormalising the Stokes vector is unbiased.
    Scene scene = defaultScene();
    Source pencil{SourceType::Ray, kIntoTheCell.origin, kIntoTheCell.direction, 0.0};
    pencil.polarisation = {PolarisationKind::Linear, 30.0, unpolarisedStokes(),
                           kIntoTheCell.direction.vector().unitOrthogonal()};
    scene.sources = {pencil};
    const OpticalScene optical(scene);
    constexpr int kBins = 18;
    TraceSettings settings;
    settings.photons = 200000;
    const TraceResult result = test::traceStandard(optical, scene.sources, settings, kBins);
    const FateTally& tally = test::fates(result);

    RayTreeSettings fine;
    fine.minWeight = 1e-12;
    fine.maxDepth = 200;
    const RayTree tree =
        traceRayTree(optical, kIntoTheCell, 1.0, fine, emittedPolarisation(pencil, kIntoTheCell.direction));
    std::vector<double> expected(kBins, 0.0);
    std::vector<StokesVector> expectedStokes(kBins, StokesVector::Zero());
    for (const RayTreeNode& node : tree.nodes) {
        if (node.event.type != EventType::Escape) continue;
        const double angle = std::acos(std::clamp(node.event.direction.dot(kIntoTheCell.direction), -1.0, 1.0));
        const auto bin = std::min(static_cast<std::size_t>(angle / std::numbers::pi * kBins), std::size_t{kBins - 1});
        expected[bin] += node.event.weight;
        ASSERT_TRUE(node.event.polarisation);
        EXPECT_NEAR(node.event.polarisation->stokes[0], node.event.weight, kWeightRounding);
        expectedStokes[bin] +=
            inScatteringPlane(*node.event.polarisation, node.event.direction, kIntoTheCell.direction);
    }
    const double n = static_cast<double>(settings.photons);
    EXPECT_NEAR(fraction(tally.absorbed(), result), tree.absorbed, monteCarloTolerance(tree.absorbed, n));
    const AngularTally::Columns columns = test::angular(result).columns();
    for (std::size_t bin = 0; bin < expected.size(); ++bin) {
        EXPECT_NEAR(fraction(test::angular(result).escapes()[bin], result), expected[bin],
                    monteCarloTolerance(expected[bin], n))
            << "bin " << bin;
        // Each photon's |Q|, |U|, |V| <= 1: the variance of a bin's sum is at most its share over n.
        const double stokesTolerance = 5.0 * std::sqrt(std::max(expected[bin], 1.0 / n) / n);
        EXPECT_NEAR(columns.stokesQ[bin], expectedStokes[bin][1], stokesTolerance) << "bin " << bin;
        EXPECT_NEAR(columns.stokesU[bin], expectedStokes[bin][2], stokesTolerance) << "bin " << bin;
        EXPECT_NEAR(columns.stokesV[bin], expectedStokes[bin][3], stokesTolerance) << "bin " << bin;
    }
    // Polarised light in, partly polarised light out: the test compares numbers that are not all zero.
    double largestQ = 0.0;
    for (const StokesVector& s : expectedStokes) largestQ = std::max(largestQ, std::abs(s[1]));
    EXPECT_GT(largestQ, 0.05);
}

}  // namespace
}  // namespace dropscope
