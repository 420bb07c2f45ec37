#include "TransportFixtures.hpp"

#include "optics/Fresnel.hpp"
#include "transport/PhotonTracer.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using testing::sceneFromJson;

TEST(PhotonTracer, RecordsEveryEventWithItsMediaReflectanceAndWeight) {
    // A pencil through the middle of a water drop inside a glass cell, index-matched nowhere, so
    // the path alternates between reflect and refract at random; whatever the path, each event
    // names the media on its two sides consistently with the one before.
    const Scene scene = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5}, "water": {"n": 1.3337})",
                                      R"({"type": "box", "min": [-3, -3, -3], "max": [3, 3, 3], "medium": "glass"},
                                         {"type": "sphere", "center": [0, 0, 0], "radius": 2, "medium": "water"})",
                                      "");
    const OpticalScene optical(scene);
    int refractions = 0;
    for (std::uint64_t photon = 0; photon < 200; ++photon) {
        PhotonRandom random(5, photon);
        std::vector<Event> path;
        const PhotonOutcome outcome =
            tracePhoton(optical, {Point(0.1, 0.2, -5), Direction(0, 0, 1)}, random, TransportSettings{}, &path);
        ASSERT_EQ(outcome.fate, PhotonFate::Escaped);
        ASSERT_EQ(path.front().type, EventType::Emit);
        ASSERT_EQ(path.back().type, EventType::Escape);
        MediumId current = path.front().from;  // air
        EXPECT_EQ(current, 0U);
        for (std::size_t k = 1; k + 1 < path.size(); ++k) {
            const Event& event = path[k];
            EXPECT_EQ(event.from, current);
            const double cosine = std::abs(path[k - 1].direction.dot(optical.octree().shape(event.shape)->normal(event.position)));
            EXPECT_DOUBLE_EQ(event.reflectance,
                             fresnelReflectance(cosine, scene.media[event.from].n, scene.media[event.to].n).unpolarised());
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
