// The bows of a water sphere per wavelength (docs/validation.md, "Rainbows in colour"): photons of each line
// leave after one and two internal reflections no nearer the forward direction than Descartes' minimum
// deviation for that line's n(lambda), and reach it, for a tabulated, a Cauchy, a Sellmeier and the built-in
// water index. Then the sun's primary bow: the width of its colours against the literature.
#include "Descartes.hpp"
#include "ValidationRuns.hpp"

#include "tally/SpectralAngularTally.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope::validation {
namespace {

// Mercury's violet and green lines and helium's red one.
constexpr double kLinesNm[] = {404.656, 546.074, 706.519};
// A traced direction comes from three or four refractions and reflections in double precision: its angle is
// exact to ~1e-13 degrees; no photon may fall beyond the caustic by more than this.
constexpr double kBeyondCausticDeg = 1e-9;
// How close the nearest photon must come to the caustic. Near it D - D_min ~ (b - b0)^2 D''/2, so the share of
// the beam within delta of the caustic on ray order p is ~ sqrt(delta); with 1e5 photons per line some 60
// (primary) and 20 (secondary) photons are expected within these bounds (measured gaps are in the log):
// a miss has a probability below e^-20.
constexpr double kPrimaryReachDeg = 0.01;
constexpr double kSecondaryReachDeg = 0.03;
constexpr std::uint64_t kPhotonsPerLine = 100'000;
// With 4e6 sunlit photons the primary edge of a 10 nm band is traced 0.21-0.22 degrees beyond its point-sun
// caustic; this lower bound tells a disk that smears the bow from one that does not (0).
constexpr double kSunMinimumSmearDeg = 0.15;
// The literature gives the bow's edges to a tenth of a degree, for colours it does not tie to wavelengths
// (red near 700 nm, violet near 400-410 nm): within 0.15 degrees.
constexpr double kLiteratureBowDeg = 0.15;

// Per wavelength band, the least scattering angle of the photons that left after one internal reflection and
// the largest of those after two: the edges of the primary and secondary bows. Min and max merge exactly.
class BowEdgeTally final : public Tally {
public:
    explicit BowEdgeTally(WavelengthBins bins)
        : bins_(bins),
          primary_(static_cast<std::size_t>(bins.count), std::numeric_limits<double>::infinity()),
          secondary_(static_cast<std::size_t>(bins.count), -std::numeric_limits<double>::infinity()) {}
    std::string_view name() const override { return "bow_edges"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<BowEdgeTally>(bins_); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<BowEdgeTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override {
        if (event.type != EventType::Escape) return;
        const std::uint64_t order = photon.state.interfaceEvents - 1;  // enter, k reflections, leave: k + 2
        if (order != 2 && order != 3) return;
        const double cosine = std::clamp(event.direction.dot(photon.state.axis), -1.0, 1.0);
        const double theta = std::acos(cosine) * 180.0 / std::numbers::pi;
        const auto band = static_cast<std::size_t>(bins_.binOf(photon.state.wavelengthNm));
        if (order == 2) primary_[band] = std::min(primary_[band], theta);
        if (order == 3) secondary_[band] = std::max(secondary_[band], theta);
    }
    void merge(const Tally& other) override {
        const BowEdgeTally& more = sameTally(*this, other);
        for (std::size_t k = 0; k < primary_.size(); ++k) {
            primary_[k] = std::min(primary_[k], more.primary_[k]);
            secondary_[k] = std::max(secondary_[k], more.secondary_[k]);
        }
    }
    void writeScores(ScoreWriter& out) const override {
        for (const double edge : primary_) out.real(edge);
        for (const double edge : secondary_) out.real(edge);
    }
    void readScores(ScoreReader& in) override {
        for (double& edge : primary_) edge = in.real();
        for (double& edge : secondary_) edge = in.real();
    }
    void report(ResultReport&) const override {}

    const std::vector<double>& primary() const { return primary_; }
    const std::vector<double>& secondary() const { return secondary_; }

private:
    WavelengthBins bins_;
    std::vector<double> primary_;
    std::vector<double> secondary_;
};

// A water drop of radius 1 mm with the given index model, under a beam of its radius with the given spectrum.
Scene dropScene(const std::string& water, const std::string& sourceKeys) {
    return parseScene(R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 546.074, "ambient": "air",
        "media": {"air": {"n": 1}, "water": )" +
                          water + R"(},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
        "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1)" +
                          sourceKeys + "}]}",
                      "drop.json");
}

BowEdgeTally traceEdges(const Scene& scene, WavelengthBins bins, std::uint64_t photons) {
    TraceSettings settings;
    settings.photons = photons;
    settings.seed = 1;
    TallySet tallies;
    tallies.add(std::make_unique<BowEdgeTally>(bins));
    const TraceResult result = runTrace(OpticalScene(scene), scene.sources, settings, tallies);
    return result.tallies.get<BowEdgeTally>();
}

struct IndexModel {
    const char* name;
    const char* json;
};
// Water-like models of each form. The test compares the tracer with Descartes for whatever n(lambda) the
// model gives, so the numbers need only be plausible: the table and the Cauchy terms are rounded water
// values; the Sellmeier terms are Daimon and Masumura's (2007) fit for water at 20 C.
const IndexModel kModels[] = {
    {"table", R"({"n": {"table_nm": [[400, 1.3435], [500, 1.3374], [600, 1.3330], [700, 1.3308], [750, 1.3297]]}})"},
    {"cauchy", R"({"n": {"cauchy_um": [1.3246, 0.00323]}})"},
    {"sellmeier", R"({"n": {"sellmeier_um": {"B": [0.5684027565, 0.1726177391, 0.02086189578, 0.1130748688],
                                             "C": [0.005101829712, 0.01821153936, 0.02620722293, 10.69792721]}}})"},
    {"builtin", R"({"n": {"builtin": "water"}})"},
};

TEST(DispersiveRainbow, EachLinesBowsAreAtDescartesMinimumDeviationForItsIndex) {
    std::string lines;
    for (const double line : kLinesNm)
        lines += std::string(lines.empty() ? "" : ", ") + "[" + formatted(line, "%.9g") + ", 1]";
    for (const IndexModel& model : kModels) {
        SCOPED_TRACE(model.name);
        const Scene scene = dropScene(model.json, R"(, "spectrum": {"lines_nm": [)" + lines + "]}");
        const WavelengthBins bins{3, kLinesNm[0], kLinesNm[2]};
        const BowEdgeTally edges = traceEdges(scene, bins, 3 * kPhotonsPerLine);
        const Medium& water = scene.media[*scene.findMedium("water")];
        for (int k = 0; k < 3; ++k) {
            const double n = mediumOpticsAt(water, kLinesNm[k], scene.unitInMetres).n;
            const double primary = descartes(n, 1).scatteringDeg;
            const double secondary = descartes(n, 2).scatteringDeg;
            const auto band = static_cast<std::size_t>(bins.binOf(kLinesNm[k]));
            const std::string line = std::string(model.name) + "_" + formatted(kLinesNm[k], "%.0f") + "nm";
            recordFigure(line + "_primary_edge_deg", formatted(primary, "%.4f"),
                         formatted(edges.primary()[band], "%.4f"),
                         "within " + formatted(kPrimaryReachDeg) + " deg above, 1e5 photons a line", false);
            recordFigure(line + "_secondary_edge_deg", formatted(secondary, "%.4f"),
                         formatted(edges.secondary()[band], "%.4f"),
                         "within " + formatted(kSecondaryReachDeg) + " deg below, 1e5 photons a line", false);
            EXPECT_GE(edges.primary()[band], primary - kBeyondCausticDeg) << line;
            EXPECT_LE(edges.primary()[band], primary + kPrimaryReachDeg) << line;
            EXPECT_LE(edges.secondary()[band], secondary + kBeyondCausticDeg) << line;
            EXPECT_GE(edges.secondary()[band], secondary - kSecondaryReachDeg) << line;
        }
        // dispersion: violet's primary bow is nearer the backward direction than red's, by about 1.5 degrees
        EXPECT_GT(edges.primary()[0] - edges.primary()[2], 1.0);
    }
}

TEST(DispersiveRainbow, TheSunsPrimaryBowHasTheWidthOfTheLiterature) {
    // Built-in water (index and absorption), the sun's spectrum and its disk: 0.266 degrees half-angle.
    constexpr double kSunRadiusDeg = 0.266;
    const Scene scene = dropScene(R"({"n": {"builtin": "water"}, "kappa": {"builtin": "water"}})",
                                  R"(, "spectrum": "sun", "divergence_deg": 0.266)");
    // 10 nm bands: the primary edge of the band from 690 to 700 nm is red's, from 400 to 410 nm violet's.
    const WavelengthBins bins{40, 380.0, 780.0};
    const BowEdgeTally edges = traceEdges(scene, bins, 4'000'000);
    const Medium& water = scene.media[*scene.findMedium("water")];
    const auto edgeOf = [&](double hiNm) { return edges.primary()[static_cast<std::size_t>(bins.binOf(hiNm - 1.0))]; };
    const auto causticOf = [&](double nm) {
        return descartes(mediumOpticsAt(water, nm, scene.unitInMetres).n, 1).scatteringDeg;
    };
    // Each band's edge: the caustic of its longest wavelength, moved towards the forward direction by up to the
    // sun's radius (a ray tilted towards the drop's axis by the sun's radius leaves tilted the same way). The
    // photons that reach the full radius come from the disk's rim and the caustic at once: few, so the traced
    // edge lies a little short of it, but always beyond the point sun's caustic by most of the radius.
    const double red = edgeOf(700.0);
    const double violet = edgeOf(410.0);
    for (const auto& [edge, nm] : {std::pair{red, 700.0}, std::pair{violet, 410.0}}) {
        const double smear = causticOf(nm) - edge;
        recordFigure("sun_primary_edge_smear_" + formatted(nm, "%.0f") + "nm_deg", "0.15 to 0.266",
                     formatted(smear, "%.3f"), "the disk's radius at most", false);
        EXPECT_LE(smear, kSunRadiusDeg + kBeyondCausticDeg) << nm;
        EXPECT_GE(smear, kSunMinimumSmearDeg) << nm;
    }
    // The bow's radius around the antisolar point is 180 degrees less the scattering angle. The literature
    // (L. Cowley, Atmospheric Optics, "Primary rainbow"): red's outer edge at 42.4 degrees, violet's at 40.7,
    // for a point sun: 1.7 degrees of colour, to which the sun's disk adds its diameter. The traced edges, less
    // the sun's radius, estimate the point sun's.
    const double redRadius = 180.0 - red - kSunRadiusDeg;
    const double violetRadius = 180.0 - violet - kSunRadiusDeg;
    const double colourWidth = redRadius - violetRadius;
    const std::string photons = ", 4e6 photons";
    recordFigure("sun_primary_red_radius_deg", "42.4", formatted(redRadius, "%.2f"), "0.15 deg" + photons, false);
    recordFigure("sun_primary_violet_radius_deg", "40.7", formatted(violetRadius, "%.2f"), "0.15 deg" + photons, false);
    recordFigure("sun_primary_colour_width_deg", "1.7", formatted(colourWidth, "%.2f"), "0.15 deg" + photons, false);
    recordFigure("sun_primary_width_with_disk_deg", "2.2", formatted(colourWidth + 2 * kSunRadiusDeg, "%.2f"),
                 "0.15 deg" + photons, false);
    EXPECT_NEAR(redRadius, 42.4, kLiteratureBowDeg);
    EXPECT_NEAR(violetRadius, 40.7, kLiteratureBowDeg);
    EXPECT_NEAR(colourWidth, 1.7, kLiteratureBowDeg);
}

}  // namespace
}  // namespace dropscope::validation
