// Detectors in the real app: a trace fills each detector's image window (opened from the Results panel), the
// Results panel's energy budget adds up to the photons and its ray orders plot opens, the Paths panel filters
// the recorded photons by ray order and by detector hit, and partial results arrive while a run goes on.
#include "AppHarness.hpp"

#include "gui/PathFilter.hpp"
#include "gui/TraceActions.hpp"
#include "tally/BudgetTally.hpp"
#include "tally/DetectorTallies.hpp"
#include "tally/OrderTally.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>
#include <thread>

namespace dropscope::gui::testing {
namespace {

// A water droplet under a beam as wide as it: a far-field camera at the antisolar point (the bows), a
// screen between the beam's origin and the droplet that counts the light coming back, an absorbing plate
// behind the droplet (photons end there: detected), and the absorption in each shape.
constexpr const char* kDetectorScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337, "kappa": 1e-6}},
  "shapes": [{"type": "sphere", "name": "drop", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "beam", "origin": [0, 0, -4], "direction": [0, 0, 1], "radius": 1}],
  "detectors": [
    {"type": "far_field", "name": "sky", "look": [0, 0, 1], "up": [0, 1, 0], "fov_deg": 110, "pixels": [40, 40]},
    {"type": "plane", "name": "screen", "center": [0, 0, -2.5], "normal": [0, 0, 1], "up": [0, 1, 0],
     "size": [10, 10], "pixels": [32, 32], "side": "front"},
    {"type": "plane", "name": "plate", "center": [0, 0, 3], "normal": [0, 0, -1], "up": [0, 1, 0],
     "size": [3, 3], "pixels": [8, 8], "absorbing": true},
    {"type": "shape_absorption", "name": "absorbed"}
  ],
  "view": {"eye": [9, 5, -9], "target": [0, 0, 0]}
})";

constexpr int kWidth = 1280;
constexpr int kHeight = 1000;  // the Results panel tall enough for its detector lines

class DetectorResultsUi : public ::testing::Test {
protected:
    DetectorResultsUi() : harness_(kDetectorScene, kWidth, kHeight) {}
    const TallySet& tallies() { return shownTrace(harness_).tallies; }
    AppHarness harness_;
};

TEST_F(DetectorResultsUi, TheAppTracesTheOrdersTheDetectorsAndTheBudget) {
    fire(harness_, 3000, 10);
    EXPECT_NE(tallies().find<OrderTally>(), nullptr);
    EXPECT_NE(tallies().find<BudgetTally>(), nullptr);
    const auto detectors = tallies().all<DetectorTally>();
    ASSERT_EQ(detectors.size(), 4U);
    for (const DetectorTally* tally : detectors) {
        EXPECT_GT(tally->hits(), 0U) << tally->detector().name;
        EXPECT_EQ(tally->photons(), 3000U);
    }
}

TEST_F(DetectorResultsUi, EachDetectorsWindowShowsItsImageAndTheHoverReadout) {
    fire(harness_, 5000, 10);
    harness_.frame();
    for (const std::string name : {"sky", "screen", "plate"}) {
        ASSERT_TRUE(harness_.clickItem("detector " + name)) << name;
        harness_.frames(2);
        const DetectorView& view = harness_.state().traces.views.detectors.at(name);
        EXPECT_TRUE(view.open) << name;
        ASSERT_TRUE(view.image) << name;
        EXPECT_EQ(view.image->photons, 5000U);
        EXPECT_GT(view.image->maxDensity, 0.0) << name;
        const double total = std::accumulate(view.image->fraction.begin(), view.image->fraction.end(), 0.0);
        EXPECT_GT(total, 0.0) << name;
        ASSERT_TRUE(harness_.item("detector " + name + " image"));
    }
    // The sky's image in true colour, and its brightest pixel's readout under the mouse.
    const DetectorImage& sky = *harness_.state().traces.views.detectors.at("sky").image;
    EXPECT_EQ(sky.sky.size(), 3U * 40U * 40U);
    const auto brightest = static_cast<int>(
        std::max_element(sky.density.begin(), sky.density.end(),
                         [](double a, double b) { return std::isfinite(b) && (!std::isfinite(a) || a < b); }) -
        sky.density.begin());
    const int ix = brightest % 40;
    const int iy = brightest / 40;
    // Bring the sky's window to the front, then hover that pixel.
    ASSERT_TRUE(harness_.clickItem("detector sky"));
    harness_.frames(2);
    const auto image = harness_.item("detector sky image");
    ASSERT_TRUE(image);
    const float cell = (image->maxX - image->minX) / 40.0f;
    harness_.moveMouse(image->minX + cell * (static_cast<float>(ix) + 0.5f),
                       image->maxY - cell * (static_cast<float>(iy) + 0.5f));
    harness_.frame();
    const auto readout = harness_.item("detector sky readout");
    ASSERT_TRUE(readout);
    const std::string pixel = "pixel (" + std::to_string(ix) + ", " + std::to_string(iy) + ")";
    EXPECT_NE(readout->text.find(pixel), std::string::npos) << readout->text;
    EXPECT_NE(readout->text.find("radiance"), std::string::npos) << readout->text;
}

TEST_F(DetectorResultsUi, TheBudgetAddsUpToThePhotonsAndTheOrdersPlotOpens) {
    fire(harness_, 4000, 10);
    const BudgetTally& budget = tallies().get<BudgetTally>();
    const auto sum = [](const auto& counts) { return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0}); };
    const std::uint64_t escaped = budget.escapedElsewhere() + sum(budget.escapedInto());
    EXPECT_EQ(escaped + sum(budget.absorbedBy()) + sum(budget.detectedBy()) + sum(budget.lostBy()), 4000U);
    EXPECT_GT(sum(budget.detectedBy()), 0U);   // the plate ends photons
    EXPECT_GT(sum(budget.escapedInto()), 0U);  // the sky sees the bows
    harness_.frame();
    ASSERT_TRUE(harness_.clickItem("budget window"));
    harness_.frames(2);
    EXPECT_TRUE(harness_.state().traces.views.budgetOpen);
    for (const std::string end : {"escaped", "absorbed", "detected", "lost"}) harness_.item("budget " + end);
    ASSERT_TRUE(harness_.clickItem("orders plot"));
    harness_.frames(2);
    EXPECT_TRUE(harness_.state().traces.views.ordersPlot.open);
    harness_.item("Ray orders frame 0");
}

TEST_F(DetectorResultsUi, ThePathFilterKeepsOnlyTheChosenOrderAndDetector) {
    fire(harness_, 400, 400);
    const auto& paths = shownTrace(harness_).paths;
    ASSERT_TRUE(harness_.choose("order", "p2"));
    harness_.frame();
    EXPECT_EQ(harness_.state().traces.pathFilter.order, 4);
    const std::vector<Detector>& detectors = harness_.state().traces.trace->outcome.scene.detectors;
    const std::vector<int> p2 = filterPaths(paths, detectors, harness_.state().traces.pathFilter);
    EXPECT_GT(p2.size(), 0U);
    EXPECT_LT(p2.size(), paths.size());
    for (int k : p2) {
        const PhotonPath& path = paths[static_cast<std::size_t>(k)];
        EXPECT_EQ(rayOrder(path), 2) << "photon " << path.photon;
        int interfaces = 0;
        for (const Event& event : path.events) {
            interfaces +=
                event.type == EventType::Reflect || event.type == EventType::Refract || event.type == EventType::Tir;
        }
        EXPECT_EQ(interfaces, 3) << "photon " << path.photon;
    }
    // p2 photons come back towards the source: every one that escaped is in the sky's view or elsewhere,
    // and those hitting the screen are a subset of them.
    ASSERT_TRUE(harness_.choose("hit", "screen"));
    harness_.frame();
    ASSERT_EQ(harness_.state().traces.pathFilter.detector, std::optional<std::size_t>(1));
    const std::vector<int> onScreen = filterPaths(paths, detectors, harness_.state().traces.pathFilter);
    EXPECT_GT(onScreen.size(), 0U);
    EXPECT_LE(onScreen.size(), p2.size());
    for (int k : onScreen) EXPECT_NE(std::find(p2.begin(), p2.end(), k), p2.end());
    // The plate: photons ending on it (a Detect event), none of order p2.
    ASSERT_TRUE(harness_.choose("order", "any"));
    ASSERT_TRUE(harness_.choose("hit", "plate"));
    harness_.frame();
    const std::vector<int> onPlate = filterPaths(paths, detectors, harness_.state().traces.pathFilter);
    EXPECT_GT(onPlate.size(), 0U);
    for (int k : onPlate) {
        EXPECT_EQ(paths[static_cast<std::size_t>(k)].fate, PhotonFate::Detected);
        EXPECT_NE(rayOrder(paths[static_cast<std::size_t>(k)]), 2);
    }
}

TEST_F(DetectorResultsUi, DetectorImagesFillInWhileARunGoesOn) {
    harness_.state().traces.fire.photons = 400000;
    harness_.state().traces.fire.paths = 0;
    harness_.press(kKeySpace);
    std::uint64_t seen = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (harness_.state().traces.job.running() && std::chrono::steady_clock::now() < end) {
        harness_.frame();
        const ShownTallies shown = shownTallies(harness_.state().traces);
        if (shown.filling) {
            EXPECT_LT(shown.photons, 400000U);
            EXPECT_EQ(shown.tallies->get<BudgetTally>().photons(), shown.photons);
            seen = std::max(seen, shown.photons);
            harness_.state().traces.job.cancel();  // one partial is enough: stop the run
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_GT(seen, 0U) << "no partial result arrived before the run ended";
    ASSERT_TRUE(harness_.waitForTrace());
    EXPECT_FALSE(shownTallies(harness_.state().traces).filling);
}

}  // namespace
}  // namespace dropscope::gui::testing
