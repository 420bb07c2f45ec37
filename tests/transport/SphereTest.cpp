// A sphere under a wide beam, traced without polarisation (the unpolarised Fresnel reflectance at every
// interface), against a reference computed ray order by ray order with that model (van de Hulst's
// geometric optics; the polarised tracer has its own reference, PolarisedSphereTest.cpp): a ray of impact parameter b =
// sin(theta_i) enters with theta_t = asin(b/n), every chord inside has length L = 2a cos(theta_t) and meets the surface
// at theta_t again, where the reflectance R is the same as outside (Stokes). Order p leaves with weight
//   p = 0: R,   p >= 1: (1-R)^2 R^(p-1) tau^p,   tau = exp(-sigma L),
// deviated by D_p = 2(theta_i - theta_t) + (p-1)(pi - 2 theta_t) (p >= 1), pi - 2 theta_i (p = 0).
// Impact parameters are uniform over the disk: weight d(b^2) = 2 cos(theta_i) d cos(theta_i).
#include "TransportFixtures.hpp"
#include "transport/TallyExpectations.hpp"

#include "optics/Fresnel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace dropscope {
namespace {

using test::fraction;
using testing::monteCarloTolerance;
using testing::sceneFromJson;

constexpr double kWater = 1.3337;
constexpr double kBeamRadius = 1.25;  // the sphere has radius 1: 64% of the photons hit it
constexpr int kBins = 36;

struct SphereReference {
    std::vector<double> angular = std::vector<double>(kBins, 0.0);  // escaped fraction per bin
    double absorbed = 0.0;
};

SphereReference reference(double sigma) {
    constexpr int kSteps = 400000;  // midpoint rule in cos(theta_i); bins are 5 degrees wide
    const double hit = 1.0 / (kBeamRadius * kBeamRadius);
    SphereReference result;
    result.angular[0] = 1.0 - hit;  // the photons that miss go straight on
    const auto deposit = [&](double deviation, double weight) {
        const double angle = std::acos(std::cos(deviation));  // folded into [0, pi]
        const auto bin = std::min(static_cast<int>(angle / std::numbers::pi * kBins), kBins - 1);
        result.angular[static_cast<std::size_t>(bin)] += weight;
    };
    for (int step = 0; step < kSteps; ++step) {
        const double cosI = (step + 0.5) / kSteps;
        const double weight = hit * 2.0 * cosI / kSteps;
        const double thetaI = std::acos(cosI);
        const double thetaT = std::asin(std::sin(thetaI) / kWater);
        const double r = fresnelReflectance(cosI, 1.0, kWater).unpolarised();
        const double tau = std::exp(-sigma * 2.0 * std::cos(thetaT));
        deposit(std::numbers::pi - 2.0 * thetaI, weight * r);
        result.absorbed += weight * (1 - r) * (1 - tau) / (1 - r * tau);
        double inside = weight * (1 - r) * tau;  // arriving at the far wall for the first time
        for (int p = 1; inside > 1e-15 * weight; ++p) {
            deposit(2 * (thetaI - thetaT) + (p - 1) * (std::numbers::pi - 2 * thetaT), inside * (1 - r));
            inside *= r * tau;
        }
    }
    return result;
}

TraceResult traceSphere(double sigma, std::uint64_t photons) {
    const Scene scene =
        sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337, "sigma": )" + std::to_string(sigma) + "}",
                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                      R"({"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": 1.25})");
    TraceSettings settings;
    settings.photons = photons;
    settings.seed = 11;
    settings.transport.polarisation = PolarisationModel::None;
    return test::traceStandard(OpticalScene(scene), scene.sources, settings, kBins);
}

class SphereUnderABeam : public ::testing::TestWithParam<double> {};

TEST_P(SphereUnderABeam, AngularDistributionAndAbsorptionMatchTheRayOrderReference) {
    const double sigma = GetParam();
    constexpr std::uint64_t kPhotons = 400000;
    const TraceResult result = traceSphere(sigma, kPhotons);
    const FateTally& tally = test::fates(result);
    const SphereReference expected = reference(sigma);
    const double n = static_cast<double>(kPhotons);

    EXPECT_EQ(tally.lost(), 0U);
    EXPECT_NEAR(fraction(tally.unscattered(), result), 1 - 1 / (kBeamRadius * kBeamRadius),
                monteCarloTolerance(0.36, n));
    EXPECT_NEAR(fraction(tally.absorbed(), result), expected.absorbed, monteCarloTolerance(expected.absorbed, n));
    for (int bin = 0; bin < kBins; ++bin) {
        const double p = expected.angular[static_cast<std::size_t>(bin)];
        EXPECT_NEAR(fraction(test::angular(result).escapes()[static_cast<std::size_t>(bin)], result), p,
                    monteCarloTolerance(p, n))
            << "bin " << bin * 5 << "-" << bin * 5 + 5 << " degrees";
    }
}

INSTANTIATE_TEST_SUITE_P(ClearAndAbsorbing, SphereUnderABeam, ::testing::Values(0.0, 0.4));

class SphereWithAPointSourceInside : public ::testing::TestWithParam<PolarisationModel> {};

TEST_P(SphereWithAPointSourceInside, TotalInternalReflectionTrapsExactlyTheRaysPastTheCriticalAngle) {
    // Trapped past the critical angle, or reflected `cap` times in a row: capLossInsideSphere, with s and p
    // apart or the unpolarised model's reflectance. (Here the two differ by only 1.5e-5: the trapped share
    // dominates; PolarisedSphereTest.cpp tells the models apart.)
    const bool polarised = GetParam() == PolarisationModel::Stokes;
    constexpr double kGlass = 1.5;
    constexpr double kR0 = 0.9;
    constexpr std::uint32_t kCap = 30;
    const Scene scene = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5})",
                                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"})",
                                      R"({"type": "point", "origin": [0.9, 0, 0]})");
    TraceSettings settings;
    settings.photons = 200000;
    settings.transport.maxEvents = kCap;
    settings.transport.polarisation = GetParam();
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settings);

    const double expectedLost = testing::capLossInsideSphere(kGlass, kR0, kCap, polarised);
    const FateTally& tally = test::fates(result);
    EXPECT_NEAR(fraction(tally.lost(), result), expectedLost, monteCarloTolerance(expectedLost, 2e5));
    EXPECT_EQ(tally.lost(), tally.lost(LostReason::EventCap));
    EXPECT_EQ(tally.escaped() + tally.lost(), tally.photons());
    // The closed form of the trapped share alone, sqrt(1 - (a / (n r0))^2), bounds it from below.
    const double trapped = std::sqrt(1 - std::pow(1 / (kGlass * kR0), 2));
    EXPECT_GT(fraction(tally.lost(), result), trapped - monteCarloTolerance(trapped, 2e5));
}

INSTANTIATE_TEST_SUITE_P(StokesAndNone, SphereWithAPointSourceInside,
                         ::testing::Values(PolarisationModel::Stokes, PolarisationModel::None));

}  // namespace
}  // namespace dropscope
