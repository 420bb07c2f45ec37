// The GUI's background trace: the same result as runTrace called directly, cancelled and restarted
// without blocking the UI thread for long, errors carried back instead of std::terminate.
#include "gui/TraceJob.hpp"
#include "scene/SceneLoader.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/TallyExpectations.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <string>
#include <thread>

namespace dropscope {
namespace {

using test::expectSameTally;

using gui::TraceJob;
using gui::TraceOutcome;
using Clock = std::chrono::steady_clock;

const std::string kScenes = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/";
const std::string kTestScenes = std::string(DROPSCOPE_TEST_DATA_DIR) + "/scenes/";

// A hang check, not a performance limit: every wait below ends in well under a second when it works.
constexpr std::chrono::seconds kHangLimit{10};
// Photons enough that no run of the cloud ends by itself during a test (about 1e5 photons a second).
constexpr std::uint64_t kBigRun = 50'000'000;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Polls `done` every millisecond; false when it is still not true after `limit` seconds.
template <class Done>
bool waitUntil(Done done, double limit = static_cast<double>(kHangLimit.count())) {
    const auto start = Clock::now();
    while (!done()) {
        if (secondsSince(start) > limit) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

// Waits until the job's run ends and takes its outcome.
TraceOutcome finish(TraceJob& job) {
    EXPECT_TRUE(waitUntil([&] { return !job.running(); })) << "the run did not end";
    std::optional<TraceOutcome> outcome = job.takeResult();
    EXPECT_TRUE(outcome.has_value());
    return outcome ? std::move(*outcome) : TraceOutcome();
}

// Waits until the job's photons have started.
bool waitUntilTracing(const TraceJob& job) {
    return waitUntil([&] { return job.progress().done > 0 || !job.running(); }) && job.running();
}

TraceSettings settings(std::uint64_t photons) {
    TraceSettings settings;
    settings.photons = photons;
    settings.paths = 40;
    settings.seed = 2024;
    return settings;
}

void expectSamePaths(const std::vector<PhotonPath>& a, const std::vector<PhotonPath>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].photon, b[i].photon);
        EXPECT_EQ(a[i].source, b[i].source);
        EXPECT_EQ(a[i].fate, b[i].fate);
        ASSERT_EQ(a[i].events.size(), b[i].events.size()) << "path " << i;
        for (std::size_t k = 0; k < a[i].events.size(); ++k) {
            const Event& x = a[i].events[k];
            const Event& y = b[i].events[k];
            EXPECT_EQ(x.type, y.type);
            EXPECT_EQ(x.position, y.position);
            EXPECT_EQ(x.direction.vector(), y.direction.vector());
            EXPECT_EQ(x.shape, y.shape);
            EXPECT_EQ(x.weight, y.weight);
        }
    }
}

TEST(TraceJob, DeliversWhatRunTraceGivesDirectly) {
    const Scene direct = loadScene(kScenes + "default.json");
    const TraceResult expected = test::traceStandard(OpticalScene(direct), direct.sources, settings(20000));

    TraceJob job;
    job.start(loadScene(kScenes + "default.json"), settings(20000));
    const TraceOutcome outcome = finish(job);

    EXPECT_FALSE(outcome.error.has_value());
    EXPECT_FALSE(outcome.result.partial);
    EXPECT_EQ(outcome.result.requested, 20000U);
    expectSameTally(outcome.result, expected);
    expectSamePaths(outcome.result.paths, expected.paths);
    // The traced scene comes back with the result: its shapes, names and media.
    ASSERT_EQ(outcome.scene.shapes.size(), direct.shapes.size());
    EXPECT_EQ(outcome.scene.shapeNames, direct.shapeNames);
    ASSERT_EQ(outcome.scene.media.size(), direct.media.size());
    EXPECT_EQ(outcome.scene.media[1].name, direct.media[1].name);
    // The progress ends at the whole run.
    EXPECT_EQ(job.progress().done, 20000U);
    EXPECT_EQ(job.progress().total, 20000U);
    EXPECT_FALSE(job.progress().buildingOctree);
}

TEST(TraceJob, ARayThroughOneSphereGivesTheDirectResult) {
    const Scene direct = loadScene(kTestScenes + "one_sphere.json");
    const TraceResult expected = test::traceStandard(OpticalScene(direct), direct.sources, settings(1000));

    TraceJob job;
    job.start(loadScene(kTestScenes + "one_sphere.json"), settings(1000));
    const TraceOutcome outcome = finish(job);
    ASSERT_FALSE(outcome.error.has_value()) << *outcome.error;
    expectSameTally(outcome.result, expected);
    expectSamePaths(outcome.result.paths, expected.paths);
    EXPECT_EQ(outcome.scene.shapeNames, std::vector<std::string>{"drop"});
}

TEST(TraceJob, TheResultIsTakenOnceAndNotWhileRunning) {
    TraceJob job;
    EXPECT_FALSE(job.running());
    EXPECT_FALSE(job.takeResult().has_value()) << "nothing was started";
    job.start(loadScene(kScenes + "cloud.json"), settings(kBigRun));
    EXPECT_TRUE(job.running()) << "running from the moment start() returns";
    EXPECT_FALSE(job.takeResult().has_value()) << "a result while the run goes on";
    job.cancel();
    const TraceOutcome outcome = finish(job);
    EXPECT_TRUE(outcome.result.partial);
    EXPECT_FALSE(job.takeResult().has_value()) << "the same result twice";
}

TEST(TraceJob, CancellingABigRunEndsItSoonWithAPartialResult) {
    TraceJob job;
    job.start(loadScene(kScenes + "cloud.json"), settings(kBigRun));
    ASSERT_TRUE(waitUntilTracing(job));

    const auto cancelled = Clock::now();
    job.cancel();
    EXPECT_LT(secondsSince(cancelled), 0.01) << "cancel() waited for the run";
    ASSERT_TRUE(waitUntil([&] { return !job.running(); }));
    const double latency = secondsSince(cancelled);
    std::cout << "cloud.json: the run ended " << latency * 1e3 << " ms after cancel()\n";

    const TraceOutcome outcome = finish(job);
    EXPECT_FALSE(outcome.error.has_value());
    EXPECT_TRUE(outcome.result.partial);
    EXPECT_GT(test::fates(outcome.result).photons(), 0U);
    EXPECT_LT(test::fates(outcome.result).photons(), kBigRun);
    EXPECT_EQ(outcome.result.requested, kBigRun);
    const FateTally& tally = test::fates(outcome.result);
    EXPECT_EQ(tally.escaped() + tally.absorbed() + tally.lost(), tally.photons());
}

// The slowest photons there are: trapped by total internal reflection in a glass cube until the event
// cap (10,000 events each). A stop waits for the chunk of 256 photons each thread is in, so a cancel
// just as the first chunks start takes the longest there is. Both times are printed; the assertion is
// only a hang check, with the limit stretched by the chunk's time on this build (sanitizers are slow).
TEST(TraceJob, TrappedPhotonsStopWithinAChunk) {
    const std::string text =
        R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "glass": {"n": 1.5}},
            "shapes": [{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "medium": "glass"}],
            "sources": [{"type": "ray", "origin": [0.1, 0.2, 0.3], "direction": [0.6, 0.5, 0.62]}]})";
    const Scene direct = parseScene(text, "trapped.json");
    TraceSettings chunk = settings(256);
    chunk.threads = 1;
    const auto chunkStart = Clock::now();
    const TraceResult oneChunk = test::traceStandard(OpticalScene(direct), direct.sources, chunk);
    const double chunkSeconds = secondsSince(chunkStart);
    ASSERT_EQ(test::fates(oneChunk).lost(LostReason::EventCap), 256U) << "not trapped";
    const double limit = static_cast<double>(kHangLimit.count()) + 4.0 * chunkSeconds;

    TraceJob job;
    job.start(parseScene(text, "trapped.json"), settings(kBigRun));
    ASSERT_TRUE(waitUntil([&] { return !job.progress().buildingOctree; }, limit));
    const auto cancelled = Clock::now();
    job.cancel();
    ASSERT_TRUE(waitUntil([&] { return !job.running(); }, limit));
    const double latency = secondsSince(cancelled);
    std::cout << "trapped photons: one chunk takes " << chunkSeconds * 1e3 << " ms on one thread; the run ended "
              << latency * 1e3 << " ms after cancel()\n";
    EXPECT_TRUE(finish(job).result.partial);
}

TEST(TraceJob, ProgressRisesMonotonicallyWhileRunning) {
    TraceJob job;
    job.start(loadScene(kScenes + "cloud.json"), settings(kBigRun));
    EXPECT_TRUE(job.progress().buildingOctree) << "the octree comes first";
    EXPECT_EQ(job.progress().total, kBigRun);

    gui::TraceJobProgress last = job.progress();
    int rises = 0;
    bool builtOctree = false;
    const auto start = Clock::now();
    // Until five reports have raised the count (0.1 s apart), every poll at or above the one before.
    while (rises < 5 && job.running() && Clock::now() - start < kHangLimit) {
        const gui::TraceJobProgress now = job.progress();
        EXPECT_GE(now.done, last.done);
        EXPECT_GE(now.seconds, last.seconds);
        EXPECT_LE(now.done, now.total);
        EXPECT_EQ(now.total, kBigRun);
        if (!now.buildingOctree) builtOctree = true;
        EXPECT_FALSE(builtOctree && now.buildingOctree) << "back to building the octree";
        if (now.done > last.done) ++rises;
        last = now;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_EQ(rises, 5);
    EXPECT_TRUE(job.running());
    job.cancel();
    const TraceOutcome outcome = finish(job);
    // The final count is the photons traced, at least the last report's.
    EXPECT_GE(test::fates(outcome.result).photons(), last.done);
    EXPECT_EQ(job.progress().done, test::fates(outcome.result).photons());
}

TEST(TraceJob, StartingAgainCancelsTheFirstRunAndDeliversOnlyTheSecond) {
    TraceJob job;
    job.start(loadScene(kScenes + "cloud.json"), settings(kBigRun));
    ASSERT_TRUE(waitUntilTracing(job));

    const auto restarted = Clock::now();
    job.start(loadScene(kTestScenes + "one_sphere.json"), settings(1000));
    std::cout << "start() over a running cloud returned after " << secondsSince(restarted) * 1e3
              << " ms (loading the sphere, stopping the cloud)\n";
    const TraceOutcome outcome = finish(job);
    ASSERT_FALSE(outcome.error.has_value()) << *outcome.error;
    EXPECT_EQ(outcome.scene.shapes.size(), 1U) << "not the sphere's outcome";
    EXPECT_EQ(outcome.result.requested, 1000U);
    EXPECT_FALSE(outcome.result.partial);
    EXPECT_EQ(test::fates(outcome.result).photons(), 1000U);
    EXPECT_FALSE(job.takeResult().has_value()) << "the cancelled run's outcome came too";
}

TEST(TraceJob, ASceneWithoutSourcesDeliversAnErrorNotACrash) {
    TraceJob job;
    job.start(loadScene(kTestScenes + "no_sources.json"), settings(1000));
    const TraceOutcome outcome = finish(job);
    ASSERT_TRUE(outcome.error.has_value());
    EXPECT_EQ(*outcome.error, "the scene has no light sources");
    EXPECT_EQ(outcome.result.photons, 0U);
    EXPECT_EQ(outcome.scene.shapes.size(), 1U) << "the scene comes back with the error";

    // The job works again afterwards.
    job.start(loadScene(kTestScenes + "one_sphere.json"), settings(100));
    EXPECT_FALSE(finish(job).error.has_value());
}

TEST(TraceJob, DestroyingItDuringARunDoesNotHang) {
    const auto start = Clock::now();
    double destroyed = 0.0;
    {
        TraceJob job;
        job.start(loadScene(kScenes + "cloud.json"), settings(kBigRun));
        ASSERT_TRUE(waitUntilTracing(job));
        destroyed = secondsSince(start);
    }
    const double latency = secondsSince(start) - destroyed;
    std::cout << "the destructor returned " << latency * 1e3 << " ms after a running cloud\n";
    EXPECT_LT(latency, static_cast<double>(kHangLimit.count()));
}

// The octree is built before runTrace looks at the stop flag, so this waits for the whole build.
TEST(TraceJob, DestroyingItWhileTheOctreeIsBuiltDoesNotHang) {
    Scene cloud = loadScene(kScenes + "cloud.json");
    const auto start = Clock::now();
    {
        TraceJob job;
        job.start(std::move(cloud), settings(kBigRun));
        EXPECT_TRUE(job.progress().buildingOctree);
    }
    const double latency = secondsSince(start);
    std::cout << "the destructor returned " << latency * 1e3 << " ms after starting the cloud (octree build)\n";
    EXPECT_LT(latency, static_cast<double>(kHangLimit.count()));
}

}  // namespace
}  // namespace dropscope
