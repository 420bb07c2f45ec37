#include "transport/TallyExpectations.hpp"
#include "transport/TransportFixtures.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <utility>

namespace dropscope {
namespace {

using test::expectSameTally;

Scene defaultScene() { return loadScene(DROPSCOPE_SOURCE_DIR "/assets/scenes/default.json"); }

TraceSettings settingsFor(std::uint64_t photons, int threads) {
    TraceSettings settings;
    settings.photons = photons;
    settings.threads = threads;
    settings.paths = 50;
    settings.seed = 2024;
    return settings;
}

TEST(TraceRun, OneAndTwoThreadsGiveBitIdenticalResults) {
    const Scene scene = defaultScene();
    const OpticalScene optical(scene);
    const TraceResult one = test::traceStandard(optical, scene.sources, settingsFor(30000, 1));
    const TraceResult two = test::traceStandard(optical, scene.sources, settingsFor(30000, 2));
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(two.threads, 2);
    expectSameTally(one, two);
    ASSERT_EQ(one.paths.size(), two.paths.size());
    for (std::size_t i = 0; i < one.paths.size(); ++i) {
        ASSERT_EQ(one.paths[i].events.size(), two.paths[i].events.size());
        for (std::size_t k = 0; k < one.paths[i].events.size(); ++k) {
            EXPECT_EQ(one.paths[i].events[k].position, two.paths[i].events[k].position);
            EXPECT_EQ(one.paths[i].events[k].type, two.paths[i].events[k].type);
        }
    }
}

TEST(TraceRun, EveryPhotonEndsEscapedAbsorbedOrLostExactlyOnce) {
    const Scene scene = defaultScene();
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(20000, 0));
    const FateTally& tally = test::fates(result);
    EXPECT_FALSE(result.partial);
    EXPECT_EQ(tally.photons(), 20000U);
    EXPECT_EQ(tally.escaped() + tally.absorbed() + tally.lost(), tally.photons());
    std::uint64_t binned = 0;
    for (std::uint64_t count : test::angular(result).escapes()) binned += count;
    EXPECT_EQ(binned, tally.escaped());
    std::uint64_t lostByReason = 0;
    for (std::size_t reason = 0; reason < kLostReasonCount; ++reason) {
        lostByReason += tally.lost(static_cast<LostReason>(reason));
    }
    EXPECT_EQ(lostByReason, tally.lost());
    EXPECT_EQ(tally.events().absorb, tally.absorbed());
    EXPECT_LE(tally.unscattered(), tally.escaped());
}

TEST(TraceRun, RecordedPathsAreTheFirstPhotonsAndEndTheWayTheyWereCounted) {
    const Scene scene = defaultScene();
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(1000, 2));
    ASSERT_EQ(result.paths.size(), 50U);
    for (std::size_t i = 0; i < result.paths.size(); ++i) {
        const PhotonPath& path = result.paths[i];
        EXPECT_EQ(path.photon, i);
        ASSERT_GE(path.events.size(), 2U);
        EXPECT_EQ(path.events.front().type, EventType::Emit);
        const EventType last = path.events.back().type;
        const EventType expected = path.fate == PhotonFate::Escaped    ? EventType::Escape
                                   : path.fate == PhotonFate::Absorbed ? EventType::Absorb
                                                                       : EventType::Lost;
        EXPECT_EQ(last, expected);
        for (std::size_t k = 1; k + 1 < path.events.size(); ++k) {
            const Event& event = path.events[k];
            EXPECT_NE(event.shape, RayHit::kNone);
            EXPECT_GE(event.reflectance, 0.0);
            EXPECT_LE(event.reflectance, 1.0);
            EXPECT_EQ(event.weight, 1.0);
            if (event.type == EventType::Tir) {
                EXPECT_EQ(event.reflectance, 1.0);
            }
        }
    }
}

TEST(TraceRun, ConsecutivePhotonRangesMergedAreOneRun) {
    // What the app's batches rely on: [0, 700) + [700, 1800) + [1800, 3000), their tallies merged and their
    // paths (40 recorded, across the first boundary) joined, are the run of [0, 3000).
    const Scene scene = defaultScene();
    const OpticalScene optical(scene);
    TraceSettings settings = settingsFor(3000, 2);
    settings.paths = 40;
    const TraceResult whole = test::traceStandard(optical, scene.sources, settings);
    TraceResult joined;
    for (const auto& [first, count] : {std::pair<std::uint64_t, std::uint64_t>{0, 700}, {700, 1100}, {1800, 1200}}) {
        settings.firstPhoton = first;
        settings.photons = count;
        TraceResult batch = test::traceStandard(optical, scene.sources, settings);
        if (first == 0) {
            joined = std::move(batch);
            continue;
        }
        joined.tallies.merge(batch.tallies);
        joined.photons += batch.photons;
        for (PhotonPath& path : batch.paths) joined.paths.push_back(std::move(path));
    }
    expectSameTally(whole, joined);
    ASSERT_EQ(joined.paths.size(), 40U);
    for (std::size_t i = 0; i < joined.paths.size(); ++i) {
        EXPECT_EQ(joined.paths[i].photon, i);
        ASSERT_EQ(joined.paths[i].events.size(), whole.paths[i].events.size()) << "photon " << i;
        EXPECT_EQ(joined.paths[i].events.back().position, whole.paths[i].events.back().position) << "photon " << i;
    }
}

TEST(TraceRun, PhotonsTakeTurnsBetweenSources) {
    // Two pencils, one hitting nothing (unscattered) and one hitting a sphere: half the photons each.
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                               R"({"type": "ray", "origin": [5, 5, -3], "direction": [0, 0, 1]},
           {"type": "ray", "origin": [0.3, 0, -3], "direction": [0, 0, 1]})");
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(1001, 2));
    EXPECT_EQ(test::fates(result).unscattered(), 501U);
    EXPECT_EQ(result.paths[0].source, 0U);
    EXPECT_EQ(result.paths[1].source, 1U);
}

TEST(TraceRun, AStopRequestEndsTheRunEarlyWithConsistentPartialResults) {
    const Scene scene = defaultScene();
    std::atomic<bool> stop{false};
    TraceControl control;
    control.stop = &stop;
    control.interval = 0.0;
    int reports = 0;
    control.onProgress = [&](const TraceProgress& progress) {
        ++reports;
        EXPECT_EQ(progress.total, 10000000U);
        EXPECT_LE(progress.done, progress.total);
        stop = true;
    };
    const TraceResult result =
        test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(10000000, 2), 180, control);
    EXPECT_GE(reports, 1);
    EXPECT_TRUE(result.partial);
    EXPECT_GT(test::fates(result).photons(), 0U);
    EXPECT_LT(test::fates(result).photons(), 10000000U);
    EXPECT_EQ(test::fates(result).escaped() + test::fates(result).absorbed() + test::fates(result).lost(),
              test::fates(result).photons());
    for (const PhotonPath& path : result.paths) EXPECT_FALSE(path.events.empty());
}

TEST(TraceRun, AStopBeforeTheStartTracesNothing) {
    const Scene scene = defaultScene();
    const std::atomic<bool> stop{true};
    TraceControl control;
    control.stop = &stop;
    const TraceResult result =
        test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(1000, 1), 180, control);
    EXPECT_TRUE(result.partial);
    EXPECT_EQ(test::fates(result).photons(), 0U);
    EXPECT_TRUE(result.paths.empty());
}

TEST(TraceRun, RefusesARunWithoutSourcesAndAnAngularTallyWithoutBins) {
    const Scene scene = defaultScene();
    const OpticalScene optical(scene);
    EXPECT_THROW(test::traceStandard(optical, {}, settingsFor(10, 1)), std::invalid_argument);
    EXPECT_THROW(AngularTally(0), std::invalid_argument);
}

TEST(TraceRun, RefusesASourceWhosePolarisationCannotBeUsed) {
    const Scene scene = loadScene(DROPSCOPE_SOURCE_DIR "/assets/scenes/default.json");
    std::vector<Source> sources = scene.sources;
    sources.front().polarisation.kind = PolarisationKind::Linear;  // and no reference
    TraceSettings settings;
    settings.photons = 10;
    try {
        runTrace(OpticalScene(scene), sources, settings, standardTallies(18, PolarisationModel::Stokes));
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), "source 0: polarisation reference: must be a finite, non-zero vector");
    }
}

}  // namespace
}  // namespace dropscope
