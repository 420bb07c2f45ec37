// Mie theory in the real app: a trace of one water droplet with the Fire panel's diffraction switch on is compared
// with Lorenz-Mie theory in the Results panel (x, Q_sca, g; traced / Mie by band) and in its plot; a scene that is
// not spheres says why there is no comparison.
#include "AppHarness.hpp"

#include "gui/plot/PlotWindowState.hpp"
#include "tally/FateTally.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace dropscope::gui::testing {
namespace {

// x = 2 pi a / lambda = 300 at 532 nm; a beam 1.5 times as wide as the droplet.
constexpr const char* kDropletScene = R"({
  "dropscope": 1, "unit": "um", "wavelength_nm": 532, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 25.4007, "medium": "water"}],
  "sources": [{"type": "beam", "origin": [0, 0, -100], "direction": [0, 0, 1], "radius": 38.1}]
})";

constexpr int kWidth = 1280;
constexpr int kHeight = 1000;

TEST(MieUi, OneDropletsTraceIsComparedWithMieTheory) {
    AppHarness harness(kDropletScene, kWidth, kHeight);
    ASSERT_TRUE(harness.clickItem("diffraction"));
    EXPECT_TRUE(harness.state().traces.fire.diffraction);
    fire(harness, 100000, 10);
    harness.frames(2);
    const auto summary = harness.item("mie summary");
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->text, "Mie: one sphere, x 300, m 1.334+0i");
    const auto efficiencies = harness.item("mie efficiencies");
    ASSERT_TRUE(efficiencies);
    EXPECT_EQ(efficiencies->text.rfind("  Q_sca 2.0", 0), 0u) << efficiencies->text;
    EXPECT_GT(shownTrace(harness).tallies.get<FateTally>().photons(), 0u);

    // Unfolded, the band table: the side band and the diffraction peak close to Mie theory's even at 1e5 photons
    // (docs/validation.md: 0.994 and 0.978 at x = 200, 0.999 and 0.99 at x = 1000).
    ASSERT_TRUE(harness.clickItem("mie bands"));
    harness.frames(2);
    for (const char* band : {"0-1", "15-60"}) {
        const auto ratio = harness.item(std::string("mie ratio ") + band);
        ASSERT_TRUE(ratio) << band;
        EXPECT_NEAR(std::stod(ratio->text), 1.0, 0.05) << band;
    }
    // The plot's Mie curves are over the traced ones: its export has them beside the traced columns.
    ASSERT_TRUE(harness.clickItem("results plot"));
    harness.frames(2);
    ASSERT_TRUE(harness.state().ui.panels.angularPlot.open);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("dropscope-mie-ui-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".csv");
    harness.state().ui.panels.angularPlot.exportPath = file.string();
    ASSERT_TRUE(harness.clickItem("Angular distribution export"));
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "scattering angle (deg),fraction per sr,Mie theory,DoLP,-P12/P11,Mie -P12/P11");
    std::filesystem::remove(file);
}

TEST(MieUi, ASceneOfOtherShapesSaysWhyThereIsNoComparison) {
    AppHarness harness(R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "glass": {"n": 1.5}},
      "shapes": [{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "medium": "glass"}],
      "sources": [{"type": "beam", "origin": [0, 0, -4], "direction": [0, 0, 1], "radius": 0.5}]})",
                       kWidth, kHeight);
    fire(harness, 1000, 10);
    harness.frames(2);
    const auto summary = harness.item("mie summary");
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->text, "Mie theory: none (shape 0 is a box: Mie theory is for spheres)");
    EXPECT_FALSE(harness.state().traces.trace->outcome.mie);
}

TEST(MieUi, ADivergentBeamIsNotComparedWithAPlaneWavesTheory) {
    AppHarness divergent(R"({"dropscope": 1, "unit": "um", "wavelength_nm": 532, "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 25, "medium": "water"}],
      "sources": [{"type": "beam", "origin": [0, 0, -100], "direction": [0, 0, 1], "radius": 38, "divergence_deg": 0.3}]})",
                         kWidth, kHeight);
    fire(divergent, 1000, 10);
    divergent.frames(2);
    EXPECT_EQ(divergent.item("mie summary")->text,
              "Mie theory: none (a source diverges; Mie theory here is for a plane wave)");
}

// One app at a time (ImGui's context is global).
TEST(MieUi, ALargeDropletIsLeftToTheCommandLine) {
    // x = 11810: more than half a second of Mie theory beside each trace.
    AppHarness large(R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
      "sources": [{"type": "beam", "origin": [0, 0, -4], "direction": [0, 0, 1], "radius": 1}]})",
                     kWidth, kHeight);
    fire(large, 1000, 10);
    large.frames(2);
    EXPECT_NE(large.item("mie summary")->text.find("dropscope mie --scene"), std::string::npos)
        << large.item("mie summary")->text;
}

}  // namespace
}  // namespace dropscope::gui::testing
