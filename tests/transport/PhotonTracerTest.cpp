#include "TransportFixtures.hpp"
#include "transport/TallyExpectations.hpp"

#include "optics/Fresnel.hpp"
#include "optics/Stokes.hpp"
#include "transport/PhotonTracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace dropscope {
namespace {

using testing::sceneFromJson;

class PhotonTracerModels : public ::testing::TestWithParam<PolarisationModel> {};

TEST_P(PhotonTracerModels, RecordsEveryEventWithItsMediaReflectanceAndWeight) {
    // A pencil through the middle of a water drop inside a glass cell, index-matched nowhere, so
    // the path alternates between reflect and refract at random; whatever the path, each event
    // names the media on its two sides consistently with the one before. Without polarisation R is the
    // unpolarised Fresnel reflectance; with it, R lies between Rs and Rp, and the Stokes vector after each
    // event has I = 1 (the photon's weight) and a reference axis perpendicular to the direction.
    const PolarisationModel model = GetParam();
    const Scene scene = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5}, "water": {"n": 1.3337})",
                                      R"({"type": "box", "min": [-3, -3, -3], "max": [3, 3, 3], "medium": "glass"},
                                         {"type": "sphere", "center": [0, 0, 0], "radius": 2, "medium": "water"})",
                                      "");
    const OpticalScene optical(scene);
    TransportSettings settings;
    settings.polarisation = model;
    int refractions = 0;
    for (std::uint64_t photon = 0; photon < 200; ++photon) {
        PhotonRandom random(5, photon);
        std::vector<Event> path;
        EventRecorder recorder(path);
        const PhotonOutcome outcome =
            tracePhoton(optical, {Point(0.1, 0.2, -5), Direction(0, 0, 1)}, random, settings, &recorder);
        ASSERT_EQ(outcome.fate, PhotonFate::Escaped);
        ASSERT_EQ(path.front().type, EventType::Emit);
        ASSERT_EQ(path.back().type, EventType::Escape);
        MediumId current = path.front().from;  // air
        EXPECT_EQ(current, 0U);
        for (std::size_t k = 1; k + 1 < path.size(); ++k) {
            const Event& event = path[k];
            EXPECT_EQ(event.from, current);
            const double cosine =
                std::abs(path[k - 1].direction.dot(optical.octree().shape(event.shape)->normal(event.position)));
            const FresnelReflectance r = fresnelReflectance(cosine, scene.media[event.from].n, scene.media[event.to].n);
            if (model == PolarisationModel::None) {
                EXPECT_DOUBLE_EQ(event.reflectance, r.unpolarised());
                EXPECT_FALSE(event.polarisation);
            } else {
                EXPECT_GE(event.reflectance, std::min(r.s, r.p) - 1e-15);
                EXPECT_LE(event.reflectance, std::max(r.s, r.p) + 1e-15);
                ASSERT_TRUE(event.polarisation);
                EXPECT_NEAR(event.polarisation->stokes[0], 1.0, 1e-15);
                EXPECT_LE(degreeOfPolarisation(event.polarisation->stokes), 1.0 + 1e-12);
                EXPECT_NEAR(event.polarisation->reference.norm(), 1.0, 1e-14);
                EXPECT_NEAR(event.polarisation->reference.dot(event.direction.vector()), 0.0, 1e-14);
            }
            if (event.type == EventType::Refract) {
                current = event.to;
                ++refractions;
            }
        }
        EXPECT_EQ(current, 0U);
        EXPECT_EQ(path.back().from, 0U);
        EXPECT_EQ(outcome.finalDirection.vector(), path.back().direction.vector());
    }
    EXPECT_GT(refractions, 600);  // most photons refract four times
}

INSTANTIATE_TEST_SUITE_P(StokesAndNone, PhotonTracerModels,
                         ::testing::Values(PolarisationModel::Stokes, PolarisationModel::None));

TEST(PhotonTracer, APhotonThatHitsABoxEdgeIsLostWithThatReason) {
    const Scene scene = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5})",
                                      R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "medium": "glass"})", "");
    PhotonRandom random(1, 0);
    const PhotonOutcome outcome =
        tracePhoton(OpticalScene(scene), {Point(-1, -1, 0.5), Direction(1, 1, 0)}, random, TransportSettings{});
    EXPECT_EQ(outcome.fate, PhotonFate::Lost);
    EXPECT_EQ(outcome.lostReason, LostReason::UndefinedNormal);
}

TEST(PhotonTracer, APhotonThatMeetsNothingEscapesUnscattered) {
    const Scene scene = sceneFromJson(R"("air": {"n": 1})", "", "");
    PhotonRandom random(1, 0);
    const PhotonOutcome outcome =
        tracePhoton(OpticalScene(scene), {Point(0, 0, 0), Direction(0, 1, 0)}, random, TransportSettings{});
    EXPECT_EQ(outcome.fate, PhotonFate::Escaped);
    EXPECT_FALSE(outcome.metSurface);
    EXPECT_EQ(outcome.events, EventCounts{});
}

}  // namespace
}  // namespace dropscope

namespace dropscope {
namespace {

TEST(PhotonTracer, TheEventCapEndsAPhotonAfterExactlyThatManyInterfaceEvents) {
    // Inside a glass cube, a direction whose cosines are all below cos(theta_c) = sqrt(1 - 1/n^2)
    // reflects totally on every face for ever.
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5})",
                               R"({"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "medium": "glass"})", "");
    const OpticalScene optical(scene);
    for (std::uint32_t cap : {1U, 7U, 500U}) {
        PhotonRandom random(1, 0);
        std::vector<Event> path;
        EventRecorder recorder(path);
        TransportSettings settings;
        settings.maxEvents = cap;
        const PhotonOutcome outcome =
            tracePhoton(optical, {Point(0.1, 0.2, 0.3), Direction(0.6, 0.5, 0.62)}, random, settings, &recorder);
        EXPECT_EQ(outcome.fate, PhotonFate::Lost);
        EXPECT_EQ(outcome.lostReason, LostReason::EventCap);
        EXPECT_EQ(outcome.events.tir, cap);
        ASSERT_EQ(path.size(), cap + 2U);  // emit, cap TIRs, lost
        EXPECT_EQ(path.back().type, EventType::Lost);
        EXPECT_EQ(path.back().lostReason, LostReason::EventCap);
    }
}

TEST(PhotonTracer, APhotonEmittedOnASurfaceIsInsideTheShapeWhenItHeadsInward) {
    // A point source on a drop's surface: the inward half of the photons start in the water. Those at
    // more than the critical angle to the normal stay trapped by total internal reflection (every
    // chord of a sphere meets the wall at the angle it started with), a share
    // 1/2 cos(theta_c) = 1/2 sqrt(1 - 1/n^2) of all photons, and end at the event cap; none is lost
    // for any other reason.
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                               R"({"type": "point", "origin": [0, 0, 1]})");
    TraceSettings settings;
    settings.photons = 20000;
    settings.paths = 200;
    settings.transport.maxEvents = 50;
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settings);
    for (const PhotonPath& path : result.paths) {
        const Event& emit = path.events.front();
        EXPECT_EQ(emit.from, emit.direction.z() < 0 ? 1U : 0U) << path.photon;  // water : air
    }
    const FateTally& tally = test::fates(result);
    EXPECT_EQ(tally.lost(), tally.lost(LostReason::EventCap));
    // From the surface (r0 = 1) the inward half behaves as from inside; the outward half escapes.
    const double expectedLost = 0.5 * testing::capLossInsideSphere(1.3337, 1.0, 50, true);  // polarised (default)
    EXPECT_GT(expectedLost, 0.5 * std::sqrt(1 - 1 / (1.3337 * 1.3337)));                    // the trapped share
    EXPECT_NEAR(test::fraction(tally.lost(), result), expectedLost, testing::monteCarloTolerance(expectedLost, 2e4));
}

TEST(PhotonTracer, ADistantSourceHitsATinyDropletAsWellAsANearOne) {
    // A 5 um droplet under a beam of twice its radius: a quarter of the photons hit it, whether the
    // beam starts 1 mm or 1e8 mm away (hit points are computed from the scene, not the source).
    for (double distance : {1.0, 1e5, 1e8}) {
        const Scene scene =
            testing::sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                                   R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.005, "medium": "water"})",
                                   R"({"type": "beam", "origin": [0, 0, )" + std::to_string(-distance) +
                                       R"(], "direction": [0, 0, 1], "radius": 0.01})");
        TraceSettings settings;
        settings.photons = 40000;
        const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settings);
        EXPECT_EQ(test::fates(result).lost(), 0U) << distance;
        EXPECT_NEAR(test::fraction(test::fates(result).unscattered(), result), 0.75,
                    testing::monteCarloTolerance(0.75, 4e4))
            << distance;
    }
}

TEST(PhotonTracer, AbsorptionOnTheWayFromADistantSourceIsStillSampled) {
    // An absorbing ambient, a source 10 mm before the scene: exp(-sigma * 10) of the photons arrive.
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1, "sigma": 0.1}, "water": {"n": 1})",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                               R"({"type": "ray", "origin": [0, 0, -11], "direction": [0, 0, 1]})");
    TraceSettings settings;
    settings.photons = 40000;
    settings.paths = 2000;
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settings);
    EXPECT_EQ(test::fates(result).absorbed(), test::fates(result).photons());  // the ambient goes on for ever
    int beforeTheDrop = 0;
    for (const PhotonPath& path : result.paths) beforeTheDrop += path.events.back().position.z() < -1.0;
    const double expected = 1.0 - std::exp(-0.1 * 10.0);
    EXPECT_NEAR(beforeTheDrop / 2000.0, expected, testing::monteCarloTolerance(expected, 2000));
}

}  // namespace
}  // namespace dropscope
