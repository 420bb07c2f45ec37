// Wavelengths in the app, driven through the panels as a user would: a source's spectrum and divergence
// set in the Fire panel land in the document (numbers that make no spectrum, and light a medium is not
// defined at, are refused with the reason), a dispersion model chosen in the Media panel's Dispersion
// window lands in the document and its n is plotted, the paths can be coloured by wavelength, and with
// wavelength bands the Results plot has a curve per band in the band's colour.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "render/Layers.hpp"
#include "tally/SpectralAngularTally.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace dropscope::gui::testing {
namespace {

// kAxisScene's water given as a table over 400-700 nm only: light outside it cannot be traced.
constexpr const char* kTableWaterScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": {"table_nm": [[400, 1.34], [700, 1.33]]}}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]}],
  "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
})";

// A water droplet with water's own n under a beam of sunlight: the rainbow's colours.
constexpr const char* kSunlitScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": {"builtin": "water"}}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1, "spectrum": "sun"}],
  "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
})";

// A document value computed twice in double precision (the app's draft and the closed form here).
constexpr double kRounding = 1e-12;

const Medium& mediumNamed(AppHarness& harness, const std::string& name) {
    for (const Medium& medium : harness.state().scene.document().media()) {
        if (medium.name == name) return medium;
    }
    ADD_FAILURE() << "no medium " << name;
    return harness.state().scene.document().media().front();
}

std::string status(AppHarness& harness) { return harness.state().ui.status.text(); }

TEST(SpectralUi, ASpectrumAndADivergenceSetInTheFirePanelLandInTheDocument) {
    AppHarness harness(kAxisScene);
    ASSERT_FALSE(firstSource(harness).spectrum) << "the scene's line";
    ASSERT_TRUE(harness.choose("spectrum", "sun"));
    ASSERT_TRUE(firstSource(harness).spectrum);
    EXPECT_EQ(*firstSource(harness).spectrum, Spectrum::sun());
    harness.frame();
    ASSERT_TRUE(harness.typeInto("divergence (deg)", "0.266"));
    EXPECT_FALSE(harness.state().ui.status.error()) << status(harness);
    EXPECT_EQ(firstSource(harness).divergenceDeg, 0.266);

    // Each is one undo step.
    harness.press('Z', true);
    EXPECT_EQ(firstSource(harness).divergenceDeg, 0.0);
    EXPECT_EQ(*firstSource(harness).spectrum, Spectrum::sun());
    harness.press('Z', true);
    EXPECT_FALSE(firstSource(harness).spectrum);

    // A uniform spectrum starts at 400-700 nm; its range typed backwards makes no spectrum: refused, unchanged.
    ASSERT_TRUE(harness.choose("spectrum", "uniform"));
    EXPECT_EQ(*firstSource(harness).spectrum, Spectrum::uniform(400.0, 700.0));
    harness.frame();
    const std::uint64_t revision = harness.state().scene.document().revision();
    ASSERT_TRUE(harness.typeInto("range (nm)", "800"));
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_EQ(status(harness).rfind("source not changed: spectrum uniform: ", 0), 0u) << status(harness);
    EXPECT_EQ(harness.state().scene.document().revision(), revision);
    EXPECT_EQ(*firstSource(harness).spectrum, Spectrum::uniform(400.0, 700.0));
}

TEST(SpectralUi, LightAMediumIsNotDefinedAtIsRefusedWithTheReason) {
    AppHarness harness(kTableWaterScene);
    const std::uint64_t revision = harness.state().scene.document().revision();
    ASSERT_TRUE(harness.choose("spectrum", "sun"));  // 380-780 nm, beyond the table
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_EQ(status(harness).rfind("source not changed: ", 0), 0u) << status(harness);
    EXPECT_NE(status(harness).find("water"), std::string::npos) << status(harness);
    EXPECT_EQ(harness.state().scene.document().revision(), revision);
    EXPECT_FALSE(firstSource(harness).spectrum);
}

TEST(SpectralUi, ADispersionModelChosenInTheMediaPanelLandsInTheDocumentAndIsPlotted) {
    AppHarness harness(kAxisScene);
    ASSERT_TRUE(harness.clickItem("dispersion water"));
    harness.frames(2);
    ASSERT_TRUE(harness.state().ui.panels.mediaPanel.dispersionOpen);
    ASSERT_TRUE(harness.choose("n form", "builtin"));
    EXPECT_FALSE(harness.state().ui.status.error()) << status(harness);
    const Medium& water = mediumNamed(harness, "water");
    ASSERT_TRUE(water.nModel);
    EXPECT_EQ(*water.nModel, SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 20.0));
    EXPECT_EQ(water.n, water.nModel->at(532.0)) << "the value at the scene wavelength";
    harness.frame();
    const auto range = harness.item("n plot range");
    ASSERT_TRUE(range);
    char expected[96];
    std::snprintf(expected, sizeof expected, "n %.6g at 380 nm, %.6g at 780 nm", water.nModel->at(380.0),
                  water.nModel->at(780.0));
    EXPECT_EQ(range->text, expected);

    // Water at 80 C: a lower index.
    const double at20 = water.n;
    ASSERT_TRUE(harness.typeInto("temperature (C)", "80"));
    EXPECT_EQ(*mediumNamed(harness, "water").nModel,
              SpectralFunction::builtin(Material::Water, OpticalQuantity::N, 80.0));
    EXPECT_LT(mediumNamed(harness, "water").n, at20);

    // Cauchy starts with n unchanged at the scene wavelength.
    const double before = mediumNamed(harness, "water").n;
    ASSERT_TRUE(harness.choose("n form", "Cauchy"));
    const Medium& cauchy = mediumNamed(harness, "water");
    ASSERT_TRUE(cauchy.nModel);
    EXPECT_EQ(cauchy.nModel->kind(), SpectralFunction::Kind::Cauchy);
    EXPECT_NEAR(cauchy.n, before, kRounding);
    EXPECT_GT(cauchy.nModel->at(400.0), cauchy.nModel->at(700.0)) << "normal dispersion";

    // kappa from water's table; then back to a number, as the medium began.
    ASSERT_TRUE(harness.choose("kappa form", "builtin"));
    ASSERT_TRUE(mediumNamed(harness, "water").kappaModel);
    EXPECT_EQ(*mediumNamed(harness, "water").kappaModel,
              SpectralFunction::builtin(Material::Water, OpticalQuantity::Kappa));
    harness.frame();
    ASSERT_TRUE(harness.choose("n form", "number"));
    EXPECT_FALSE(mediumNamed(harness, "water").nModel);
    EXPECT_NEAR(mediumNamed(harness, "water").n, before, kRounding);
}

TEST(SpectralUi, ATableRowOutOfOrderIsRefusedAndNothingChanges) {
    AppHarness harness(kTableWaterScene);
    ASSERT_TRUE(harness.clickItem("dispersion water"));
    harness.frames(2);
    const std::uint64_t revision = harness.state().scene.document().revision();
    ASSERT_TRUE(harness.typeInto("n rows 1", "300"));  // 400 nm, then 300 nm
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_EQ(status(harness).rfind("medium not changed: ", 0), 0u) << status(harness);
    EXPECT_EQ(harness.state().scene.document().revision(), revision);
    const auto& points = mediumNamed(harness, "water").nModel->tablePointsNm();
    EXPECT_EQ(points.back().first, 700.0);

    // A row added 50 nm past the last: the table now reaches 750 nm.
    ASSERT_TRUE(harness.clickItem("n rows add"));
    EXPECT_FALSE(harness.state().ui.status.error()) << status(harness);
    EXPECT_EQ(mediumNamed(harness, "water").nModel->domainNm(), (std::pair{400.0, 750.0}));
}

TEST(SpectralUi, ColouringByWavelengthGivesEachPathItsWavelengthsColour) {
    AppHarness harness(kSunlitScene);
    fire(harness);
    const std::vector<PhotonPath>& paths = shownTrace(harness).paths;
    ASSERT_GT(paths.size(), 1u);
    EXPECT_NE(paths[0].wavelengthNm, paths[1].wavelengthNm) << "drawn from the sun's spectrum";
    const render::Anchor anchor{};
    const auto colours = [](const render::LineBatch& batch, std::size_t count) {
        std::vector<render::Colour> result;
        for (std::size_t v = 0; v < count && v < batch.vertices().size(); ++v)
            result.push_back(batch.vertices()[v].colour);
        return result;
    };
    // The colours of the segments outside the droplets, then of their chords (kept apart: render/Chords.hpp).
    const auto coloured = [&](render::PathColouring colouring) {
        render::LineBatch lines(anchor);
        render::LineBatch chords(anchor);
        const render::ChordSplit split{harness.state().scene.document().octree(), chords};
        render::addPhotonPaths(lines, paths, 1.0, colouring, &split);
        return std::pair{colours(lines, lines.vertices().size()), colours(chords, chords.vertices().size())};
    };
    const auto byWavelength = coloured(render::PathColouring::Wavelength);
    ASSERT_NE(coloured(render::PathColouring::Weight), byWavelength);

    ASSERT_TRUE(harness.choose("colour", "wavelength"));
    EXPECT_EQ(harness.state().view.layers.pathColouring, render::PathColouring::Wavelength);
    const render::SceneLayers& layers = harness.app().viewport().layers();
    EXPECT_EQ(colours(layers.lines, byWavelength.first.size()), byWavelength.first);
    EXPECT_EQ(colours(layers.chords, layers.chords.vertices().size()), byWavelength.second);

    // The event table says the selected photon's wavelength.
    harness.press(kKeyRight);
    const auto wavelength = harness.item("photon wavelength");
    ASSERT_TRUE(wavelength);
    char expected[32];
    std::snprintf(expected, sizeof expected, "%.6g nm;", paths[0].wavelengthNm);
    EXPECT_EQ(wavelength->text, expected);
}

TEST(SpectralUi, WithWavelengthBandsTheResultsPlotHasACurvePerBand) {
    AppHarness harness(kSunlitScene);
    ASSERT_TRUE(harness.typeInto("wavelength bins", "6"));
    EXPECT_EQ(harness.state().traces.fire.wavelengthBins, 6);
    fire(harness, 2000, 0);
    const auto* spectral = shownTrace(harness).tallies.find<SpectralAngularTally>();
    ASSERT_NE(spectral, nullptr);
    EXPECT_EQ(spectral->wavelengths().count, 6);
    EXPECT_EQ(spectral->wavelengths().loNm, 380.0);
    EXPECT_EQ(spectral->wavelengths().hiNm, 780.0);

    harness.frame();
    ASSERT_TRUE(harness.clickItem("results plot"));
    harness.frames(2);
    const plot::PlotWindowState& plot = harness.state().ui.panels.angularPlot;
    ASSERT_TRUE(plot.open);
    ASSERT_GE(plot.scaledSubPlots.size(), 2u);
    EXPECT_EQ(plot.scaledSubPlots[1], "fraction per sr, by wavelength");
    EXPECT_EQ(plot.scales[1], plot::Scale::Log);
    ASSERT_TRUE(harness.item("Angular distribution frame 1"));

    // The export names each band.
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("dropscope-spectral-ui-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".csv");
    harness.state().ui.panels.angularPlot.exportPath = file.string();
    ASSERT_TRUE(harness.clickItem("Angular distribution export"));
    EXPECT_FALSE(harness.state().ui.status.error()) << status(harness);
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("scattering angle (deg),fraction per sr,380-446.7 nm,446.7-513.3 nm,513.3-580 nm,"
                           "580-646.7 nm,646.7-713.3 nm,713.3-780 nm,",
                           0),
              0u)
        << header;
    std::filesystem::remove(file);

    // Without bands (one), the next trace has none: the plot goes back to its sub-plots.
    ASSERT_TRUE(harness.typeInto("wavelength bins", "1"));
    fire(harness, 200, 0);
    EXPECT_EQ(shownTrace(harness).tallies.find<SpectralAngularTally>(), nullptr);
    harness.frame();
    EXPECT_EQ(plot.scaledSubPlots[1], "polarisation");
}

}  // namespace
}  // namespace dropscope::gui::testing
