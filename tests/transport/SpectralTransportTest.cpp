// Photons of many wavelengths (docs/spectra.md, docs/transport.md "Wavelengths"): each draws its wavelength and
// its direction in a divergent beam from its own source stream, meets every interface with the indices at its
// wavelength and every flight with the absorption at it; the defaults trace exactly as before; the spectral
// angular tally splits the angular one by band.
#include "TransportFixtures.hpp"
#include "spectrum/KolmogorovSmirnov.hpp"

#include "run/TraceRun.hpp"
#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"
#include "tally/SpectralAngularTally.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/PhotonTracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using testing::monteCarloTolerance;
using testing::sceneFromJson;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

using test::ksStatistic;

// Exceeded by a correct sampler with probability 0.001 (the asymptotic Kolmogorov distribution); the seeds
// are fixed, so each test's statistic is the same on every run.
double ksCritical(std::size_t n) { return 1.949 / std::sqrt(static_cast<double>(n)); }

TEST(SpectralTransport, TheDivergenceConeIsUniform) {
    const Direction axis(1.0, 2.0, -0.5);
    for (const double halfAngle : {5.0, 0.266}) {
        SCOPED_TRACE(halfAngle);
        const double oneMinusCosAlpha = 1.0 - std::cos(radians(halfAngle));
        std::vector<double> u;
        std::vector<double> phi;
        Eigen::Vector3d e1;
        Eigen::Vector3d e2;
        perpendicularBasis(axis, e1, e2);
        constexpr int kDraws = 20000;
        for (int i = 0; i < kDraws; ++i) {
            PhotonRandom random(11, static_cast<std::uint64_t>(i), PhotonRandom::kSourceStream);
            const Direction d = directionInCone(axis, halfAngle, random);
            const double cosTheta = d.dot(axis.vector());
            ASSERT_GE(cosTheta, std::cos(radians(halfAngle)) - 1e-15);
            // 1 - cos theta uniform on [0, 1 - cos alpha]: equal solid angle per step; from the angle itself,
            // 2 sin^2(theta/2), so that 0.266 degrees keeps its digits
            const double theta = std::atan2(d.vector().cross(axis.vector()).norm(), cosTheta);
            u.push_back(2.0 * std::pow(std::sin(0.5 * theta), 2) / oneMinusCosAlpha);
            phi.push_back(std::atan2(d.dot(e2), d.dot(e1)));
        }
        EXPECT_LT(ksStatistic(u, [](double x) { return std::clamp(x, 0.0, 1.0); }), ksCritical(u.size()));
        EXPECT_LT(ksStatistic(phi, [](double x) { return (x + std::numbers::pi) / (2.0 * std::numbers::pi); }),
                  ksCritical(phi.size()));
        EXPECT_GT(*std::max_element(u.begin(), u.end()), 0.999);  // reaches the rim
    }
}

TEST(SpectralTransport, ASingleLineAndNoDivergenceDrawNothing) {
    Source source;
    source.direction = Direction(0, 0, 1);
    PhotonRandom used(5, 7, PhotonRandom::kSourceStream);
    const EmittedLight light = emitLight(source, Spectrum::line(633.0), used);
    EXPECT_EQ(light.wavelengthNm, 633.0);
    EXPECT_EQ(light.direction.vector(), source.direction.vector());
    PhotonRandom fresh(5, 7, PhotonRandom::kSourceStream);
    EXPECT_EQ(used.bits(), fresh.bits());
    // the source stream is not the transport stream
    EXPECT_NE(PhotonRandom(5, 7).bits(), PhotonRandom(5, 7, PhotonRandom::kSourceStream).bits());
}

// A glass sphere of Cauchy index n = 1.5 + 0.01/lambda^2 (lambda in um) under a ray at impact parameter 0.6.
Scene cauchySphere(const std::string& sourceKeys) {
    return sceneFromJson(R"("air": {"n": 1}, "glass": {"n": {"cauchy_um": [1.5, 0.01]}})",
                         R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"})",
                         R"({"type": "ray", "origin": [0, 0.6, -5], "direction": [0, 0, 1])" + sourceKeys + "}");
}

TEST(SpectralTransport, EachPhotonRefractsWithTheIndexAtItsWavelength) {
    const Scene scene = cauchySphere(R"(, "spectrum": {"lines_nm": [[400, 1], [700, 1]]})");
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 200;
    settings.paths = 200;
    settings.threads = 1;
    const TraceResult result = runTrace(optical, scene.sources, settings, standardTallies(1, PolarisationModel::None));
    int checked[2] = {0, 0};
    for (const PhotonPath& path : result.paths) {
        ASSERT_TRUE(path.wavelengthNm == 400.0 || path.wavelengthNm == 700.0) << path.wavelengthNm;
        const Event& first = path.events.at(1);
        if (first.type != EventType::Refract) continue;  // reflected at the first surface
        const double lambdaUm = path.wavelengthNm / 1000.0;
        const double n = 1.5 + 0.01 / (lambdaUm * lambdaUm);
        const double sinIncidence = 0.6;
        // the refracted ray's angle to the normal at the hit point (the outward normal is the position)
        const Eigen::Vector3d normal = first.position.normalized();
        const double sinRefraction = first.direction.vector().cross(normal).norm();
        EXPECT_NEAR(sinRefraction, sinIncidence / n, 1e-12) << path.wavelengthNm;
        ++checked[path.wavelengthNm == 400.0 ? 0 : 1];
    }
    EXPECT_GT(checked[0], 50);
    EXPECT_GT(checked[1], 50);
}

TEST(SpectralTransport, EachPhotonIsAbsorbedAtItsWavelength) {
    // An index-matched sphere (no reflection) of radius 0.5 on the ray's path: a path of 1 mm through sigma(lambda)
    const Scene scene =
        sceneFromJson(R"("air": {"n": 1}, "ink": {"n": 1, "sigma": {"table_nm": [[450, 0.5], [650, 2]]}})",
                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "medium": "ink"})",
                      R"({"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1],
                          "spectrum": {"lines_nm": [[450, 1], [650, 1]]}})");
    TraceSettings settings;
    settings.photons = 40000;
    settings.paths = settings.photons;
    const TraceResult result =
        runTrace(OpticalScene(scene), scene.sources, settings, standardTallies(1, PolarisationModel::Stokes));
    double photons[2] = {0, 0};
    double absorbed[2] = {0, 0};
    for (const PhotonPath& path : result.paths) {
        const int line = path.wavelengthNm == 450.0 ? 0 : 1;
        photons[line] += 1;
        if (path.fate == PhotonFate::Absorbed) absorbed[line] += 1;
    }
    const double expected[2] = {1.0 - std::exp(-0.5), 1.0 - std::exp(-2.0)};
    for (int line = 0; line < 2; ++line) {
        const double total = static_cast<double>(settings.photons);
        EXPECT_NEAR(photons[line] / total, 0.5, monteCarloTolerance(0.5, total));
        EXPECT_NEAR(absorbed[line] / photons[line], expected[line], monteCarloTolerance(expected[line], photons[line]));
    }
}

TEST(SpectralTransport, PhotonWavelengthsFollowTheSpectrum) {
    const Scene scene = cauchySphere(R"(, "spectrum": {"table_nm": [[400, 0], [550, 2], [700, 1]]})");
    TraceSettings settings;
    settings.photons = 20000;
    settings.paths = settings.photons;
    const TraceResult result =
        runTrace(OpticalScene(scene), scene.sources, settings, standardTallies(1, PolarisationModel::None));
    std::vector<double> wavelengths;
    for (const PhotonPath& path : result.paths) wavelengths.push_back(path.wavelengthNm);
    const Spectrum& spectrum = *scene.sources[0].spectrum;
    EXPECT_LT(ksStatistic(wavelengths, [&](double x) { return spectrum.cdf(x); }), ksCritical(wavelengths.size()));
}

// Fates and angular tallies of a run of `scene`.
TallySet traced(const Scene& scene, int threads, std::optional<WavelengthBins> bins = std::nullopt) {
    TraceSettings settings;
    settings.photons = 20000;
    settings.seed = 4;
    settings.threads = threads;
    return runTrace(OpticalScene(scene), scene.sources, settings, standardTallies(36, PolarisationModel::Stokes, bins))
        .tallies;
}

void expectSameTallies(const TallySet& a, const TallySet& b) {
    EXPECT_EQ(a.get<FateTally>(), b.get<FateTally>());
    EXPECT_EQ(a.get<AngularTally>(), b.get<AngularTally>());
}

TEST(SpectralTransport, TheSceneWavelengthAsALineTracesExactlyAsBefore) {
    const Scene plain = cauchySphere("");
    const Scene line = cauchySphere(R"(, "spectrum": {"lines_nm": [[532, 1]]}, "divergence_deg": 0)");
    expectSameTallies(traced(plain, 1), traced(line, 1));
    // another line traces differently: the index is another
    const Scene red = cauchySphere(R"(, "spectrum": {"lines_nm": [[700, 1]]})");
    EXPECT_NE(traced(plain, 1).get<AngularTally>(), traced(red, 1).get<AngularTally>());
}

TEST(SpectralTransport, SpectraAndDivergenceGiveTheSameResultOnAnyThreadCount) {
    const Scene scene = cauchySphere(R"(, "spectrum": "sun", "divergence_deg": 0.266)");
    const WavelengthBins bins{4, 380.0, 780.0};
    const TallySet one = traced(scene, 1, bins);
    const TallySet two = traced(scene, 2, bins);
    expectSameTallies(one, two);
    const auto& a = one.get<SpectralAngularTally>().bands();
    const auto& b = two.get<SpectralAngularTally>().bands();
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]) << "band " << k;
}

TEST(SpectralTransport, TheBandsAddUpToTheAngularDistribution) {
    const Scene scene = cauchySphere(R"(, "spectrum": {"uniform_nm": [400, 700]})");
    const TallySet tallies = traced(scene, 2, WavelengthBins{3, 400.0, 700.0});
    const AngularTally& angular = tallies.get<AngularTally>();
    const auto& bands = tallies.get<SpectralAngularTally>().bands();
    ASSERT_EQ(bands.size(), 3U);
    std::vector<std::uint64_t> sum(angular.escapes().size(), 0);
    std::uint64_t perBand[3] = {0, 0, 0};
    for (std::size_t k = 0; k < bands.size(); ++k) {
        EXPECT_EQ(bands[k].photons(), angular.photons());  // every band's fractions are shares of all photons
        for (std::size_t bin = 0; bin < sum.size(); ++bin) {
            sum[bin] += bands[k].escapes()[bin];
            perBand[k] += bands[k].escapes()[bin];
        }
    }
    EXPECT_EQ(sum, angular.escapes());
    // a third of a uniform spectrum in each band
    for (const std::uint64_t escapes : perBand) {
        EXPECT_NEAR(static_cast<double>(escapes) / 20000.0, 1.0 / 3.0, monteCarloTolerance(1.0 / 3.0, 20000.0));
    }
    // the bands' edges, as angular_spectral.csv writes them
    ResultReport report;
    tallies.get<SpectralAngularTally>().report(report);
    const ResultTable* table = report.table("angular_spectral");
    ASSERT_NE(table, nullptr);
    ASSERT_EQ(table->rows(), 3U * 36U);
    const auto& lo = std::get<std::vector<double>>(table->columns[0].values);
    const auto& hi = std::get<std::vector<double>>(table->columns[1].values);
    EXPECT_EQ(lo.front(), 400.0);
    EXPECT_EQ(hi.front(), 500.0);
    EXPECT_EQ(lo[36], 500.0);
    EXPECT_EQ(hi.back(), 700.0);
}

TEST(SpectralTransport, WavelengthBinsHoldBothEnds) {
    const WavelengthBins bins{3, 450.0, 650.0};
    EXPECT_EQ(bins.binOf(450.0), 0);
    EXPECT_EQ(bins.binOf(650.0), 2);  // the longest line is in the last bin
    EXPECT_EQ(bins.binOf(516.0), 0);
    EXPECT_EQ(bins.binOf(517.0), 1);
    EXPECT_EQ(bins.edgeNm(3), 650.0);
    EXPECT_NO_THROW((WavelengthBins{1, 532.0, 532.0}.check()));
    EXPECT_THROW((WavelengthBins{2, 532.0, 532.0}.check()), std::invalid_argument);
    EXPECT_THROW((WavelengthBins{0, 400.0, 700.0}.check()), std::invalid_argument);
}

TEST(SpectralTransport, ARunRefusesLightAMediumIsNotDefinedFor) {
    const Scene scene = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": {"table_nm": [[500, 1.5], [600, 1.49]]}})",
                                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"})",
                                      R"({"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]})");
    std::vector<Source> sources = scene.sources;
    sources[0].spectrum = Spectrum::uniform(450.0, 550.0);  // as the app could set it
    TraceSettings settings;
    settings.photons = 10;
    try {
        runTrace(OpticalScene(scene), sources, settings, standardTallies(1, PolarisationModel::Stokes));
        FAIL() << "no error";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()),
                  "medium glass n: the spectrum's 450 nm to 550 nm is not within 500 nm to 600 nm, where it is "
                  "defined (the light of source 0)");
    }
    sources[0].divergenceDeg = 95.0;
    sources[0].spectrum.reset();
    EXPECT_THROW(runTrace(OpticalScene(scene), sources, settings, standardTallies(1, PolarisationModel::Stokes)),
                 std::invalid_argument);
}

}  // namespace
}  // namespace dropscope
