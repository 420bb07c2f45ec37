// The Results panel's plot window in the real app: opened from the panel after a trace, its readout
// under the mouse, and its CSV export (whole, or refused with a reason and no file).
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/plot/PlotReadout.hpp"
#include "tally/AngularTally.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace dropscope::gui::testing {
namespace {

constexpr const char* kFrame = "Angular distribution frame 0";
constexpr const char* kExport = "Angular distribution export";

std::filesystem::path scratch(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("dropscope-plot-ui-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" + name);
}

std::vector<std::string> linesOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

void clickCentre(AppHarness& harness, const ItemRect& rect) {
    harness.click(0.5f * (rect.minX + rect.maxX), 0.5f * (rect.minY + rect.maxY));
}

// The app after a trace of the head-on sphere (photons escape straight on and straight back) with the
// plot window opened from the Results panel.
class PlotUi : public ::testing::Test {
protected:
    PlotUi() : harness_(kAxisScene) {
        harness_.state().traces.fire.photons = 500;
        harness_.press(kKeySpace);
        EXPECT_TRUE(harness_.waitForTrace());
        harness_.frame();
        const auto button = harness_.itemRects().find("results plot");
        EXPECT_NE(button, harness_.itemRects().end()) << "the Results panel shows no Plot button";
        if (button != harness_.itemRects().end()) clickCentre(harness_, button->second);
        harness_.frames(2);
    }
    const AngularTally& angular() { return harness_.state().traces.trace->outcome.result.tallies.get<AngularTally>(); }
    ItemRect rect(const std::string& name) {
        const auto found = harness_.itemRects().find(name);
        EXPECT_NE(found, harness_.itemRects().end()) << name << " not drawn";
        return found == harness_.itemRects().end() ? ItemRect{} : found->second;
    }
    plot::PlotWindowState& plotState() { return harness_.state().ui.panels.angularPlot; }

    AppHarness harness_;
};

TEST_F(PlotUi, TheReadoutGivesTheBinUnderTheMouse) {
    ASSERT_TRUE(plotState().open);
    // The angular distribution on a log scale; the polarisation below it, linear.
    EXPECT_EQ(plotState().scales, (std::vector<plot::Scale>{plot::Scale::Log, plot::Scale::Linear}));
    const ItemRect frame = rect(kFrame);
    const std::vector<double> perSteradian = angular().columns().perSteradian;
    ASSERT_EQ(perSteradian.size(), 180u);
    ASSERT_GT(perSteradian.back(), 0.0) << "the reflection straight back";
    // 179.7 degrees, or up to a pixel (0.4 degrees) below it where ImGui floors the mouse position:
    // nearest to the last bin's centre, 179.5.
    harness_.moveMouse(frame.minX + 179.7f / 180.0f * (frame.maxX - frame.minX), 0.5f * (frame.minY + frame.maxY));
    ASSERT_TRUE(plotState().hovered);
    ASSERT_EQ(plotState().hovered->samples.size(), 1u);
    const plot::CurveSample& sample = plotState().hovered->samples[0];
    EXPECT_EQ(sample.index, 179u);
    EXPECT_EQ(sample.x, 179.5);
    EXPECT_EQ(sample.y, perSteradian.back());
    const std::vector<std::string> lines = plot::readoutLines(*plotState().hovered, "scattering angle (deg)");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "scattering angle (deg) = 179.5");
    char value[32];
    std::snprintf(value, sizeof value, "%.6g", perSteradian.back());
    EXPECT_EQ(lines[1], std::string("fraction per sr = ") + value);
}

TEST_F(PlotUi, ExportWritesOneRowPerAngularBin) {
    const std::filesystem::path file = scratch("angular.csv");
    plotState().exportPath = file.string();
    clickCentre(harness_, rect(kExport));
    EXPECT_FALSE(harness_.state().ui.status.error()) << harness_.state().ui.status.text();
    EXPECT_NE(harness_.state().ui.status.text().find("exported 180 rows"), std::string::npos)
        << harness_.state().ui.status.text();
    const std::vector<std::string> lines = linesOf(file);
    ASSERT_EQ(lines.size(), 1u + static_cast<std::size_t>(angular().bins()));
    EXPECT_EQ(lines[0], "scattering angle (deg),fraction per sr,DoLP,-P12/P11");
    EXPECT_EQ(lines[1].substr(0, 4), "0.5,");
    EXPECT_EQ(lines[180].substr(0, 6), "179.5,");
    std::filesystem::remove(file);
}

TEST_F(PlotUi, AnExportIntoAMissingDirectoryIsRefusedAndWritesNothing) {
    const std::filesystem::path directory = scratch("no-such-directory");
    plotState().exportPath = (directory / "angular.csv").string();
    clickCentre(harness_, rect(kExport));
    EXPECT_TRUE(harness_.state().ui.status.error());
    EXPECT_EQ(harness_.state().ui.status.text().rfind("plot not exported: ", 0), 0u)
        << harness_.state().ui.status.text();
    EXPECT_FALSE(std::filesystem::exists(directory));
}

}  // namespace
}  // namespace dropscope::gui::testing
