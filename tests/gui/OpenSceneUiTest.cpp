// Opening a scene starts the panels afresh: what they kept from the old scene (a filter typed into the
// shape list, the generator's fields, the octree's statistics, a plot option) does not survive it.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/Actions.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace dropscope::gui::testing {
namespace {

// One droplet: an octree of one level.
constexpr const char* kOneDroplet = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}]
})";

std::size_t cellsOf(const std::vector<LevelStatistics>& levels) {
    std::size_t cells = 0;
    for (const LevelStatistics& level : levels) cells += level.cells;
    return cells;
}

TEST(OpenSceneUi, OpeningASceneStartsThePanelsAfresh) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("dropscope-open-scene-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".json");
    std::ofstream(file) << kOneDroplet;

    AppHarness harness(kCloudScene);
    PanelState& panels = harness.state().ui.panels;
    panels.scenePanel.filter = "water";
    panels.scenePanel.cloud.count = 7;
    panels.angularPlot.open = true;
    panels.angularPlot.scales = {plot::Scale::Linear};
    panels.angularPlot.xView = plot::AxisRange{10.0, 20.0};
    panels.angularPlot.exportPath = "elsewhere.csv";
    panels.filePrompt.screenshot.panels = true;
    harness.state().view.layers.octree = true;  // opens the Octree panel (collapsed at first), which shows them
    harness.frame();
    const auto cloudLevels = harness.state().scene.document().octree().statistics();
    ASSERT_GE(cloudLevels.size(), 3u);
    ASSERT_EQ(cellsOf(panels.octreeStatistics.levels), cellsOf(cloudLevels)) << "the Octree panel shows the cloud";

    ASSERT_TRUE(openScene(harness.state(), file)) << harness.state().ui.status.text();
    harness.frame();
    EXPECT_EQ(panels.scenePanel.filter, "") << "the old scene's filter hides the new scene's shapes";
    EXPECT_EQ(panels.scenePanel.cloud.count, CloudFields{}.count);
    EXPECT_FALSE(panels.angularPlot.open);
    EXPECT_TRUE(panels.angularPlot.scales.empty()) << "the plot's log switch is back to its default";
    EXPECT_FALSE(panels.angularPlot.xView);
    EXPECT_EQ(panels.angularPlot.exportPath, PanelState{}.angularPlot.exportPath);
    EXPECT_FALSE(panels.filePrompt.screenshot.panels);
    const auto levels = harness.state().scene.document().octree().statistics();
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_EQ(panels.octreeStatistics.levels.size(), 1u) << "the Octree panel shows the old scene's levels";
    EXPECT_EQ(cellsOf(panels.octreeStatistics.levels), cellsOf(levels));
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace dropscope::gui::testing
