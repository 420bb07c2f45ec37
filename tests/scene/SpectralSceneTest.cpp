// Wavelengths in scene files (docs/scene-format.md, "Media" and "Sources"): n, kappa and sigma as functions
// of wavelength, a source's "spectrum" and "divergence_deg", every error at its JSON path, media checked
// against every wavelength the sources emit, and the writer's round trip.
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"
#include "scene/SceneWriter.hpp"
#include "scene/WavelengthCoverage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace dropscope {
namespace {

using test::sceneErrorOf;

// A scene at 550 nm with one medium "m" as given and one ray source with the given extra keys.
std::string sceneWith(const std::string& medium, const std::string& sourceKeys = "") {
    return R"({"dropscope": 1, "wavelength_nm": 550, "media": {"m": )" + medium +
           R"(}, "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1])" + sourceKeys + "}]}";
}

Medium mediumOf(const std::string& medium, const std::string& sourceKeys = "") {
    const Scene scene = parseScene(sceneWith(medium, sourceKeys), "scene.json");
    return scene.media.at(*scene.findMedium("m"));
}

Source sourceOf(const std::string& sourceKeys) {
    return parseScene(sceneWith(R"({"n": 1.33})", sourceKeys), "scene.json").sources.at(0);
}

TEST(SpectralScene, NumbersStayNumbersWithoutModels) {
    const Medium medium = mediumOf(R"({"n": 1.5, "kappa": 1e-6})");
    EXPECT_EQ(medium.n, 1.5);
    EXPECT_FALSE(medium.dispersive());
    // 4 pi kappa / lambda with lambda = 550 nm in mm (the default unit)
    EXPECT_DOUBLE_EQ(medium.absorptionPerUnit, 4.0 * std::numbers::pi * 1e-6 / 550e-6);
    // kappa's absorption scales as 1/lambda at another wavelength; n is the number
    const MediumOptics at400 = mediumOpticsAt(medium, 400.0, 1e-3);
    EXPECT_EQ(at400.n, 1.5);
    EXPECT_DOUBLE_EQ(at400.absorptionPerUnit, medium.absorptionPerUnit * 550.0 / 400.0);
}

TEST(SpectralScene, ModelsAreEvaluatedAtTheSceneWavelength) {
    // Cauchy: n = 1.3 + 0.01 / 0.55^2
    const Medium cauchy = mediumOf(R"({"n": {"cauchy_um": [1.3, 0.01]}})");
    ASSERT_TRUE(cauchy.nModel);
    EXPECT_EQ(cauchy.nModel->kind(), SpectralFunction::Kind::Cauchy);
    EXPECT_DOUBLE_EQ(cauchy.n, 1.3 + 0.01 / (0.55 * 0.55));
    EXPECT_DOUBLE_EQ(mediumOpticsAt(cauchy, 400.0, 1e-3).n, 1.3 + 0.01 / (0.4 * 0.4));
    // a table, halfway between its points
    const Medium table =
        mediumOf(R"({"n": {"table_nm": [[500, 1.34], [600, 1.32]]}, "kappa": {"table_nm": [[500, 0], [600, 2e-9]]}})");
    EXPECT_DOUBLE_EQ(table.n, 1.33);
    EXPECT_DOUBLE_EQ(*table.kappa, 1e-9);
    EXPECT_DOUBLE_EQ(table.absorptionPerUnit, 4.0 * std::numbers::pi * 1e-9 / 550e-6);
    // Sellmeier with one term: n^2 = 1 + B l^2 / (l^2 - C)
    const Medium sellmeier = mediumOf(R"({"n": {"sellmeier_um": {"B": [1.0], "C": [0.01]}}})");
    EXPECT_DOUBLE_EQ(sellmeier.n, std::sqrt(1.0 + 0.3025 / (0.3025 - 0.01)));
    // the built-ins (vacuum indices): water about 1.3347 at 550 nm and 20 C (1.33447 relative to air at 546.1 nm,
    // times n_air 1.00027), BK7 about 1.5185
    const Medium water = mediumOf(R"({"n": {"builtin": "water"}, "kappa": {"builtin": "water"}})");
    EXPECT_NEAR(water.n, 1.3347, 3e-4);
    EXPECT_GT(*water.kappa, 0.0);
    EXPECT_NEAR(mediumOf(R"({"n": {"builtin": "bk7"}})").n, 1.5185, 2e-4);
    // warmer water has a lower index
    EXPECT_LT(mediumOf(R"({"n": {"builtin": "water", "temperature_c": 80}})").n, water.n);
    // a sigma table is per scene unit, as given
    EXPECT_DOUBLE_EQ(mediumOf(R"({"n": 1.3, "sigma": {"table_nm": [[500, 1], [600, 3]]}})").absorptionPerUnit, 2.0);
}

TEST(SpectralScene, BadModelsAreRefusedAtTheirPath) {
    const auto errorOf = [](const std::string& medium) { return sceneErrorOf(sceneWith(medium)); };
    EXPECT_EQ(errorOf(R"({"n": {"builtin": "glass"}})"),
              R"(scene.json: media.m.n.builtin: unknown material "glass" (known: water, bk7, fused_silica))");
    EXPECT_EQ(errorOf(R"({"n": {"cauchy_um": [1.3], "table_nm": []}})").find("media.m.n: unknown key"), 12U);
    EXPECT_NE(errorOf(R"({"n": {"table_nm": [[600, 1.3], [500, 1.4]]}})").find("media.m.n.table_nm: "),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"n": {"table_nm": [[500, 1.3]]}})").find("media.m.n.table_nm: "), std::string::npos);
    EXPECT_EQ(errorOf(R"({"n": {"table_nm": [[500, 1.3], [600, 0]]}})"),
              "scene.json: media.m.n.table_nm: value 0.000000 at 600.000000 nm must be > 0");
    EXPECT_EQ(errorOf(R"({"n": {"table_nm": [[500, 1.3], [600]]}})"),
              "scene.json: media.m.n.table_nm[1]: expected [lambda, value], got 1 element");
    EXPECT_EQ(errorOf(R"({"n": 1.3, "kappa": {"cauchy_um": [1e-9]}})"),
              "scene.json: media.m.kappa.cauchy_um: Cauchy's formula gives a refractive index: use it for n");
    EXPECT_EQ(errorOf(R"({"n": {"builtin": "bk7", "temperature_c": 30}})"),
              "scene.json: media.m.n.temperature_c: only water's index depends on a temperature here");
    EXPECT_NE(errorOf(R"({"n": {"builtin": "water", "temperature_c": 150}})").find("media.m.n.temperature_c: "),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"n": 1.3, "kappa": {"builtin": "bk7"}})").find("media.m.kappa.builtin: "), std::string::npos);
    EXPECT_NE(errorOf(R"({"n": {"sellmeier_um": {"B": [1, 2], "C": [0.01]}}})").find("media.m.n.sellmeier_um: "),
              std::string::npos);
    EXPECT_EQ(errorOf(R"({"n": "water"})").rfind("scene.json: media.m.n: expected a number, ", 0), 0U);
    // a model that does not reach the scene wavelength
    EXPECT_EQ(errorOf(R"({"n": {"table_nm": [[600, 1.33], [700, 1.32]]}})").rfind("scene.json: media.m.n: 550 nm", 0),
              0U);
}

TEST(SpectralScene, SourcesTakeASpectrumAndADivergence) {
    EXPECT_FALSE(sourceOf("").spectrum);
    EXPECT_EQ(sourceOf("").divergenceDeg, 0.0);
    const Source lines = sourceOf(R"(, "spectrum": {"lines_nm": [[486.13, 1], [656.27, 2]]}, "divergence_deg": 0.266)");
    ASSERT_TRUE(lines.spectrum);
    EXPECT_EQ(lines.spectrum->kind(), Spectrum::Kind::Lines);
    EXPECT_EQ(lines.spectrum->rangeNm(), (std::pair{486.13, 656.27}));
    EXPECT_EQ(lines.divergenceDeg, 0.266);
    EXPECT_EQ(sourceOf(R"(, "spectrum": {"uniform_nm": [400, 700]})").spectrum->kind(), Spectrum::Kind::Uniform);
    EXPECT_EQ(sourceOf(R"(, "spectrum": {"table_nm": [[400, 0], [700, 1]]})").spectrum->kind(), Spectrum::Kind::Table);
    const Source blackbody = sourceOf(R"(, "spectrum": {"blackbody_K": 3000, "range_nm": [400, 900]})");
    EXPECT_EQ(blackbody.spectrum->kind(), Spectrum::Kind::Blackbody);
    EXPECT_EQ(blackbody.spectrum->kelvin(), 3000.0);
    const Source sun = sourceOf(R"(, "spectrum": "sun")");
    EXPECT_EQ(sun.spectrum->kind(), Spectrum::Kind::Sun);
    EXPECT_EQ(sun.spectrum->rangeNm(), (std::pair{380.0, 780.0}));
    // the default: one line at the scene's wavelength
    EXPECT_EQ(sourceSpectrum(sourceOf(""), 550.0).rangeNm(), (std::pair{550.0, 550.0}));
    EXPECT_FALSE(sourceSpectrum(sourceOf(""), 550.0).drawsRandomNumbers());
}

TEST(SpectralScene, BadSpectraAndDivergencesAreRefusedAtTheirPath) {
    const auto errorOf = [](const std::string& keys) { return sceneErrorOf(sceneWith(R"({"n": 1.33})", keys)); };
    EXPECT_EQ(
        errorOf(R"(, "spectrum": "moon")").rfind(R"(scene.json: sources[0].spectrum: unknown spectrum "moon")", 0), 0U);
    EXPECT_NE(errorOf(R"(, "spectrum": {"uniform_nm": [700, 400]})").find("sources[0].spectrum.uniform_nm: "),
              std::string::npos);
    EXPECT_NE(errorOf(R"(, "spectrum": {"lines_nm": []})").find("sources[0].spectrum.lines_nm: "), std::string::npos);
    EXPECT_NE(errorOf(R"(, "spectrum": {"lines_nm": [[500, -1]]})").find("sources[0].spectrum.lines_nm: "),
              std::string::npos);
    EXPECT_EQ(errorOf(R"(, "spectrum": {"blackbody_K": 5000})"),
              R"(scene.json: sources[0].spectrum: missing required key "range_nm")");
    EXPECT_NE(errorOf(R"(, "spectrum": {"blackbody_K": 0, "range_nm": [400, 700]})").find("blackbody_K"),
              std::string::npos);
    EXPECT_EQ(errorOf(R"(, "divergence_deg": 90)"),
              "scene.json: sources[0].divergence_deg: a divergence must be less than 90 degrees");
    EXPECT_EQ(errorOf(R"(, "divergence_deg": -1)").rfind("scene.json: sources[0].divergence_deg: ", 0), 0U);
    EXPECT_EQ(
        sceneErrorOf(R"({"dropscope": 1, "sources": [{"type": "point", "origin": [0, 0, 0], "divergence_deg": 1}]})"),
        R"(scene.json: sources[0]: unknown key "divergence_deg" (valid keys: type, origin, polarisation, spectrum))");
}

TEST(SpectralScene, MediaMustCoverEveryWavelengthTheSourcesEmit) {
    const std::string table = R"({"n": {"table_nm": [[500, 1.34], [600, 1.32]]}})";
    EXPECT_EQ(sceneErrorOf(sceneWith(table, R"(, "spectrum": {"uniform_nm": [450, 580]})")),
              "scene.json: media.m.n: the spectrum's 450 nm to 580 nm is not within 500 nm to 600 nm, where it is "
              "defined (the light of sources[0].spectrum)");
    EXPECT_EQ(sceneErrorOf(sceneWith(table, R"(, "spectrum": {"lines_nm": [[550, 1], [650, 1]]})"))
                  .rfind("scene.json: media.m.n: 650 nm", 0),
              0U);
    EXPECT_EQ(sceneErrorOf(sceneWith(table, R"(, "spectrum": {"uniform_nm": [510, 590]})")), "no error");
    // a Cauchy index that is 0.116 at the scene's 550 nm but below zero at 520 nm
    EXPECT_NE(
        sceneErrorOf(sceneWith(R"({"n": {"cauchy_um": [2, -0.57]}})", R"(, "spectrum": {"uniform_nm": [520, 800]})"))
            .find("n is"),
        std::string::npos);
    // the check as the engine's own function
    const Scene scene = parseScene(sceneWith(table), "scene.json");
    Source wide = scene.sources[0];
    wide.spectrum = Spectrum::uniform(400.0, 700.0);
    const auto problem = findWavelengthCoverageProblem(scene.media, {wide}, scene.wavelengthNm);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->medium, *scene.findMedium("m"));
    EXPECT_EQ(problem->quantity, OpticalQuantity::N);
    EXPECT_EQ(problem->source, 0U);
    EXPECT_FALSE(findWavelengthCoverageProblem(scene.media, scene.sources, scene.wavelengthNm));
}

TEST(SpectralScene, TheWriterWritesModelsAndSpectraBack) {
    const std::string text = R"({"dropscope": 1, "wavelength_nm": 550, "media": {
        "water": {"n": {"builtin": "water", "temperature_c": 30}, "kappa": {"builtin": "water"}},
        "glass": {"n": {"sellmeier_um": {"B": [1.03961212, 0.231792344], "C": [0.00600069867, 0.0200179144]}}},
        "oil": {"n": {"cauchy_um": [1.46, 0.0045, 1e-5]}, "sigma": {"table_nm": [[380, 0.5], [800, 0.25]]}},
        "bk7": {"n": {"builtin": "bk7"}}, "plain": {"n": 1.25, "kappa": 1e-8}},
      "sources": [
        {"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1, "spectrum": "sun", "divergence_deg": 0.266},
        {"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1], "spectrum": {"lines_nm": [[450, 1], [650, 3]]}},
        {"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1], "spectrum": {"uniform_nm": [400, 700]}},
        {"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1], "spectrum": {"table_nm": [[400, 1], [700, 0]]}},
        {"type": "point", "origin": [0, 0, -5], "spectrum": {"blackbody_K": 3200, "range_nm": [400, 780]}},
        {"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]}]})";
    const Scene scene = parseScene(text, "scene.json");
    const Scene again = parseScene(sceneToJson(scene), "again.json");
    ASSERT_EQ(again.media.size(), scene.media.size());
    for (std::size_t i = 0; i < scene.media.size(); ++i) {
        SCOPED_TRACE(scene.media[i].name);
        EXPECT_EQ(again.media[i].nModel, scene.media[i].nModel);
        EXPECT_EQ(again.media[i].kappaModel, scene.media[i].kappaModel);
        EXPECT_EQ(again.media[i].sigmaModel, scene.media[i].sigmaModel);
        EXPECT_EQ(again.media[i].n, scene.media[i].n);
        EXPECT_EQ(again.media[i].kappa, scene.media[i].kappa);
        EXPECT_EQ(again.media[i].absorptionPerUnit, scene.media[i].absorptionPerUnit);
    }
    EXPECT_EQ(scene.media[*scene.findMedium("water")].nModel->temperatureC(), 30.0);
    ASSERT_EQ(again.sources.size(), scene.sources.size());
    for (std::size_t i = 0; i < scene.sources.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(again.sources[i].spectrum, scene.sources[i].spectrum);
        EXPECT_EQ(again.sources[i].divergenceDeg, scene.sources[i].divergenceDeg);
    }
    EXPECT_FALSE(again.sources.back().spectrum);
    EXPECT_NE(sceneToJson(scene).find(R"("spectrum": "sun", "divergence_deg": 0.266)"), std::string::npos);
}

}  // namespace
}  // namespace dropscope
