// A water sphere under a wide unpolarised beam, traced with Stokes vectors, against the independent ray
// optics of SphereRayOptics.hpp (docs/validation.md, "Ray optics of a sphere with s and p tracked"): the
// power of each ray order, the angular distribution, the absorbed share, the backscatter, the asymmetry
// parameter g and -P12/P11 in angular bands, each within five Monte Carlo standard deviations. For the clear
// sphere the same bounds around the unpolarised model's numbers fail: order 2 (the primary bow) is 10
// standard deviations from them, the backscatter 7 and g 5.
#include "TransportFixtures.hpp"
#include "transport/RayOrderTally.hpp"
#include "transport/SphereRayOptics.hpp"
#include "transport/TallyExpectations.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using testing::monteCarloTolerance;

constexpr double kWater = 1.3337;
constexpr int kOrders = 5;  // orders 0-4 one by one, then the rest
constexpr std::uint64_t kPhotons = 400000;
constexpr double kSigmas = 5.0;

struct SphereRun {
    TraceResult result;
    testing::SphereRayOptics reference;
};

SphereRun traceSphere(double sigma) {
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337, "sigma": )" + std::to_string(sigma) + "}",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                               R"({"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": 1})");
    TraceSettings settings;
    settings.photons = kPhotons;
    settings.seed = 17;
    TallySet tallies = standardTallies(180, PolarisationModel::Stokes);
    tallies.add(std::make_unique<test::RayOrderTally>(kOrders));
    std::vector<double> edges;
    for (int degree = 0; degree <= 180; ++degree) edges.push_back(degree);
    return {runTrace(OpticalScene(scene), scene.sources, settings, tallies),
            testing::sphereRayOptics(kWater, sigma, edges, kOrders - 1)};
}

class PolarisedSphere : public ::testing::TestWithParam<double> {};

TEST_P(PolarisedSphere, MatchesTheRayOpticsWithSAndPTrackedOrderByOrder) {
    const SphereRun run = traceSphere(GetParam());
    const bool clear = GetParam() == 0.0;
    const testing::SphereRayOptics& expected = run.reference;
    const FateTally& fates = test::fates(run.result);
    const auto& orders = run.result.tallies.get<test::RayOrderTally>();
    const double n = static_cast<double>(kPhotons);
    ASSERT_EQ(fates.lost(), 0u);

    EXPECT_NEAR(test::fraction(fates.absorbed(), run.result), expected.absorbed.intensity(),
                monteCarloTolerance(expected.absorbed.intensity(), n));
    for (int order = 0; order <= kOrders; ++order) {
        const double share = order < kOrders ? expected.orders[static_cast<std::size_t>(order)].total.intensity()
                                             : expected.higherOrders.total.intensity();
        const double unpolarised = order < kOrders
                                       ? expected.orders[static_cast<std::size_t>(order)].total.unpolarisedFresnel
                                       : expected.higherOrders.total.unpolarisedFresnel;
        const double measured = test::fraction(orders.orders()[static_cast<std::size_t>(order)], run.result);
        EXPECT_NEAR(measured, share, monteCarloTolerance(share, n)) << "order " << order;
        if (clear && order == 2) {  // the unpolarised model puts 8 % more into the primary bow
            EXPECT_GT(std::abs(measured - unpolarised), monteCarloTolerance(share, n));
        }
    }

    const double backscatter = test::fraction(orders.backscattered(), run.result);
    EXPECT_NEAR(backscatter, expected.backscattered.intensity(),
                monteCarloTolerance(expected.backscattered.intensity(), n));
    if (clear) {
        EXPECT_GT(std::abs(backscatter - expected.backscattered.unpolarisedFresnel),
                  monteCarloTolerance(expected.backscattered.intensity(), n));
    }
    const double g = orders.asymmetry();
    const double gSigma = orders.asymmetrySigma();
    EXPECT_NEAR(g, expected.asymmetry, kSigmas * gSigma);
    if (clear) {
        EXPECT_GT(std::abs(g - expected.asymmetryUnpolarisedFresnel), kSigmas * gSigma);
    }

    // The angular distribution in 5-degree bins.
    const AngularTally::Columns columns = test::angular(run.result).columns();
    for (int band = 0; band < 36; ++band) {
        double measuredBand = 0.0;
        for (int degree = 5 * band; degree < 5 * band + 5; ++degree)
            measuredBand += columns.fraction[static_cast<std::size_t>(degree)];
        const double share = testing::bandPower(expected, expected.bins, 5.0 * band, 5.0 * band + 5).intensity();
        EXPECT_NEAR(measuredBand, share, monteCarloTolerance(share, n)) << 5 * band << " degrees";
    }
    // -P12/P11 = -Q/I of the escaping light in angular bands: Alexander's dark band, the primary bow's
    // caustic, inside the bow, the glory side. Each photon's |Q| <= 1 bounds Q's variance by the share.
    for (const auto& [from, to] :
         {std::pair{130, 137}, std::pair{137, 139}, std::pair{139, 150}, std::pair{150, 170}}) {
        double q = 0.0, share = 0.0;
        for (int degree = from; degree < to; ++degree) {
            q += columns.stokesQ[static_cast<std::size_t>(degree)];
            share += columns.fraction[static_cast<std::size_t>(degree)];
        }
        const double ratio = -q / share;
        const double expectedRatio = testing::bandPower(expected, expected.bins, from, to).degreeOfPolarisation();
        const double sigma = (std::sqrt(share / n) + std::abs(ratio) * std::sqrt(share * (1 - share) / n)) / share;
        EXPECT_NEAR(ratio, expectedRatio, kSigmas * sigma) << from << "-" << to << " degrees";
    }
}

INSTANTIATE_TEST_SUITE_P(ClearAndAbsorbing, PolarisedSphere, ::testing::Values(0.0, 0.4));

}  // namespace
}  // namespace dropscope
