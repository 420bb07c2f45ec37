// What the detectors count adds up, count for count (docs/validation.md, "Detectors and ray orders"): the
// power absorbed shape by shape is the absorbed total less the ambient's, an absorbing plane ends what it counts,
// and one thread and two report the same results bit for bit.
#include "DetectorRuns.hpp"

#include "tally/BudgetTally.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dropscope::validation {
namespace {

// Three absorbing media and an absorbing ambient: an ink and a dye drop in a glass block, an ink drop above it.
// A plane "stop" absorbs whatever reaches z = 6 within 20 x 20; "beyond", at z = 7 and 10 x 10, lies in its
// shadow for every straight path from below z = 6 within |x|, |y| <= 10 (where every shape and the beam are).
const char* kAbsorbingScene = R"({"dropscope": 1, "unit": "mm", "ambient": "air",
  "media": {"air": {"n": 1, "sigma": 0.01}, "glass": {"n": 1.5, "sigma": 0.05}, "ink": {"n": 1.34, "sigma": 0.5},
            "dye": {"n": 1.4, "sigma": 2}},
  "shapes": [{"type": "box", "name": "block", "min": [-3, -3, -1], "max": [3, 3, 1], "medium": "glass"},
             {"type": "sphere", "name": "ink-in-block", "center": [-1, 0, 0], "radius": 0.5, "medium": "ink"},
             {"type": "sphere", "name": "dye-in-block", "center": [1, 0, 0], "radius": 0.5, "medium": "dye"},
             {"type": "sphere", "name": "ink-above", "center": [0, 0, 3], "radius": 0.7, "medium": "ink"}],
  "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 2.5}],
  "detectors": [{"type": "shape_absorption", "name": "absorbed"},
                {"type": "plane", "name": "stop", "center": [0, 0, 6], "normal": [0, 0, 1], "up": [0, 1, 0],
                 "size": [20, 20], "pixels": [4, 4], "absorbing": true},
                {"type": "plane", "name": "beyond", "center": [0, 0, 7], "normal": [0, 0, 1], "up": [0, 1, 0],
                 "size": [10, 10], "pixels": [2, 2]}]})";
constexpr std::uint64_t kAccountingPhotons = 500'000;

TEST(DetectorAccounting, ShapeAbsorptionAddsUpToTheAbsorbedTotal) {
    const Scene scene = parseScene(kAbsorbingScene, "absorbing.json");
    const TraceResult run = traceDetectors(scene, kAccountingPhotons);
    const FateTally& fates = test::fates(run);
    const ShapeAbsorptionTally& byShape = run.tallies.get<ShapeAbsorptionTally>();
    const BudgetTally& budget = run.tallies.get<BudgetTally>();
    std::uint64_t inShapes = 0;
    std::vector<std::uint64_t> byMedium(scene.media.size(), 0);
    byMedium[scene.ambient] = byShape.ambient();
    for (std::size_t shape = 0; shape < byShape.absorbed().size(); ++shape) {
        EXPECT_GT(byShape.absorbed()[shape], 0U) << "shape " << shape;
        inShapes += byShape.absorbed()[shape];
        byMedium[scene.shapes[shape]->mediumId()] += byShape.absorbed()[shape];
    }
    recordFigure("shape_absorption_total",
                 std::to_string(fates.absorbed() - byShape.ambient()) + " (absorbed - ambient)",
                 std::to_string(inShapes), "exact, 5e5 photons", false);
    EXPECT_GT(byShape.ambient(), 0U);
    EXPECT_EQ(inShapes + byShape.ambient(), fates.absorbed());
    EXPECT_EQ(byMedium, budget.absorbedBy());  // the budget's breakdown by medium, the same photons
}

TEST(DetectorAccounting, AnAbsorbingPlaneEndsThePhotonsItCounts) {
    const Scene scene = parseScene(kAbsorbingScene, "absorbing.json");
    const TraceResult run = traceDetectors(scene, kAccountingPhotons);
    const ResultReport report = reportOf(run);
    const std::uint64_t stopped = summaryCount(report, {"detectors", "stop", "hits"});
    const BudgetTally& budget = run.tallies.get<BudgetTally>();
    recordFigure("absorbing_plane_hits", std::to_string(test::fates(run).detected()) + " (detected)",
                 std::to_string(stopped) + ", behind it " +
                     std::to_string(summaryCount(report, {"detectors", "beyond", "hits"})),
                 "exact, 5e5 photons", false);
    EXPECT_GT(stopped, 0U);
    EXPECT_EQ(stopped, test::fates(run).detected());
    EXPECT_EQ(stopped, budget.detectedBy().at(1));  // "stop" is the scene's detector 1
    EXPECT_EQ(summaryCount(report, {"detectors", "beyond", "hits"}), 0U);
    EXPECT_EQ(test::fates(run).escaped() + test::fates(run).absorbed() + test::fates(run).detected() +
                  test::fates(run).lost(),
              run.photons);
}

// A droplet cloud with absorbing droplets and every kind of detector, with records: Stokes columns, far-field
// colour sums and hit records all merged from the threads' copies.
const char* kEveryDetectorScene = R"({"dropscope": 1, "unit": "mm", "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337, "sigma": 0.2}},
  "shapes": [{"type": "sphere", "name": "big", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "generators": [{"type": "droplet_cloud", "region": {"min": [-4, -4, 2], "max": [4, 4, 6]}, "count": 400,
    "radius": {"distribution": "lognormal", "median": 0.1, "sigma": 0.3, "max": 0.3}, "medium": "water", "seed": 3}],
  "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 2,
               "spectrum": {"uniform_nm": [450, 650]}}],
  "detectors": [{"type": "plane", "name": "screen", "center": [0, 0, 8], "normal": [0, 0, -1], "up": [0, 1, 0],
                 "size": [12, 12], "pixels": [24, 24], "record": 2000},
                {"type": "plane", "name": "wall", "center": [-5, 0, 0], "normal": [1, 0, 0], "up": [0, 1, 0],
                 "size": [6, 6], "pixels": [8, 8], "side": "front", "absorbing": true, "record": 500},
                {"type": "far_field", "name": "sky", "look": [0, 0, -1], "up": [0, 1, 0],
                 "projection": "equal_area", "fov_deg": 120, "pixels": [64, 64], "record": 2000},
                {"type": "shape_absorption", "name": "absorbed", "record": 1000}]})";
constexpr std::uint64_t kThreadPhotons = 100'000;

TEST(DetectorAccounting, OneThreadAndTwoReportTheSameResultsBitForBit) {
    const Scene scene = parseScene(kEveryDetectorScene, "every-detector.json");
    const ResultReport one = reportOf(traceDetectors(scene, kThreadPhotons, PolarisationModel::Stokes, 1));
    const ResultReport two = reportOf(traceDetectors(scene, kThreadPhotons, PolarisationModel::Stokes, 2));
    ASSERT_EQ(one.tables().size(), two.tables().size());
    for (std::size_t k = 0; k < one.tables().size(); ++k)
        EXPECT_TRUE(one.tables()[k] == two.tables()[k]) << one.tables()[k].name;
    EXPECT_TRUE(one.summary() == two.summary());
    EXPECT_TRUE(one.images() == two.images());
    EXPECT_TRUE(one == two);
    recordFigure("threads_identical_tables", std::to_string(one.tables().size()) + " tables equal",
                 one == two ? "equal" : "different", "bit for bit, 1e5 photons", false);
}

}  // namespace
}  // namespace dropscope::validation
