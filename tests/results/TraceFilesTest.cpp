// The writers behind `dropscope trace`, on results made by hand: corner cases a real run rarely hits.
#include "results/PathsJsonl.hpp"
#include "results/TableCsv.hpp"
#include "results/TraceFiles.hpp"
#include "tally/AngularTally.hpp"
#include "tally/StandardTallies.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using Json = nlohmann::json;

std::string angularCsv(const ResultReport& report) {
    std::ostringstream csv;
    writeTableCsv(*report.table("angular"), csv);
    return csv.str();
}

TEST(TraceFiles, NoPhotonTracedGivesNullFractionsAndAPartialSummary) {
    TraceResult result;
    result.tallies = standardTallies(4, PolarisationModel::Stokes);
    result.requested = 1000;
    result.partial = true;
    result.threads = 3;
    result.ranks = 4;
    TraceRunInfo info{"scene.json", 2, {}};
    const ResultReport report = traceReport(result, info);
    std::ostringstream summary;
    writeTraceSummary(report, summary);
    const Json s = Json::parse(summary.str());
    EXPECT_EQ(s["photons"], 0);
    EXPECT_EQ(s["photons_requested"], 1000);
    EXPECT_EQ(s["partial"], true);
    EXPECT_EQ(s["threads"], 3);
    EXPECT_EQ(s["ranks"], 4);
    EXPECT_EQ(s["sources"], 2);
    EXPECT_EQ(s["bins"], 4);
    for (const char* fate : {"escaped", "absorbed", "lost", "unscattered"}) EXPECT_TRUE(s["fractions"][fate].is_null());

    EXPECT_EQ(s["polarisation"], "stokes");
    EXPECT_EQ(angularCsv(report),
              "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr,stokes_q,stokes_u,stokes_v,dolp\n"
              "0,45,nan,nan,nan,nan,nan,nan\n45,90,nan,nan,nan,nan,nan,nan\n90,135,nan,nan,nan,nan,nan,nan\n"
              "135,180,nan,nan,nan,nan,nan,nan\n");
}

TEST(TraceFiles, WithoutPolarisationTheAngularTableKeepsItsFourColumns) {
    TraceResult result;
    result.tallies = standardTallies(2, PolarisationModel::None);
    TraceRunInfo info{"scene.json", 1, {}};
    info.settings.transport.polarisation = PolarisationModel::None;
    const ResultReport report = traceReport(result, info);
    std::ostringstream summary;
    writeTraceSummary(report, summary);
    EXPECT_EQ(Json::parse(summary.str())["polarisation"], "none");
    EXPECT_EQ(angularCsv(report), "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr\n0,90,nan,nan\n90,180,nan,nan\n");
}

TEST(TraceFiles, SummaryKeysComeInTheDocumentedOrder) {
    TraceResult result;
    result.tallies = standardTallies(3, PolarisationModel::Stokes);
    const ResultReport report = traceReport(result, TraceRunInfo{"scene.json", 1, {}});
    std::ostringstream summary;
    writeTraceSummary(report, summary);
    std::vector<std::string> keys;
    const nlohmann::ordered_json json = nlohmann::ordered_json::parse(summary.str());
    for (const auto& item : json.items()) keys.push_back(item.key());
    const std::vector<std::string> documented{"photons",      "seed",         "ranks",        "threads",
                                              "seconds",      "fractions",    "events",       "photons_requested",
                                              "partial",      "scene",        "bins",         "fresnel",
                                              "polarisation", "diffraction",  "max_events",   "paths",
                                              "counts",       "lost_reasons", "lost_warning", "max_lost",
                                              "sources",      "version"};
    EXPECT_EQ(keys, documented);
}

TEST(TraceFiles, AngularNumbersReadBackExactly) {
    // Three photons, one escaping at 60 degrees to its emission: bin 2 of 7 (51.4 to 77.1 degrees).
    AngularTally tally(7);
    const PhotonState state{{Point::Zero(), Direction(0, 0, 1)}};
    Event emit;
    for (std::uint64_t photon = 0; photon < 3; ++photon) tally.score(emit, {photon, 0, state});
    Event escape;
    escape.type = EventType::Escape;
    escape.direction = Direction(std::sqrt(3.0) / 2.0, 0.0, 0.5);
    tally.score(escape, {0, 0, state});
    ResultReport report;
    tally.report(report);
    std::istringstream rows(angularCsv(report));
    std::string row;
    std::getline(rows, row);
    for (int bin = 0; bin < 3; ++bin) std::getline(rows, row);
    // 360/7, 540/7, 1/3 in shortest round-trip form
    const double lo = 360.0 / 7.0;
    const double hi = 540.0 / 7.0;
    std::istringstream fields(row);
    double values[4];
    char comma = 0;
    fields >> values[0] >> comma >> values[1] >> comma >> values[2] >> comma >> values[3];
    EXPECT_EQ(values[0], lo);
    EXPECT_EQ(values[1], hi);
    EXPECT_EQ(values[2], 1.0 / 3.0);
    EXPECT_NEAR(values[3] * 2.0 * std::numbers::pi *
                    (std::cos(lo * std::numbers::pi / 180.0) - std::cos(hi * std::numbers::pi / 180.0)),
                1.0 / 3.0, 1e-15);
}

TEST(TraceFiles, PolarisedPathEventsEndWithTheirStokesVectorAndReference) {
    const std::vector<Medium> media{{"air", 1.0, {}, {}, 0.0}};
    PhotonPath path;
    path.fate = PhotonFate::Escaped;
    Event escape;
    escape.type = EventType::Escape;
    escape.direction = Direction(0, 0, 1);
    escape.polarisation = Polarisation{StokesVector(1.0, -0.5, 0.25, 0.125), Eigen::Vector3d(0, 1, 0)};
    path.events = {escape};
    std::ostringstream jsonl;
    writePathsJsonl({path}, media, jsonl);
    EXPECT_EQ(jsonl.str(), R"({"photon":0,"source":0,"wavelength_nm":0.0,"fate":"escaped","events":[)"
                           R"({"type":"escape","position":[0.0,0.0,0.0],"direction":[0.0,0.0,1.0],"shape":null,)"
                           R"("medium_from":"air","medium_to":"air","R":null,"weight":1.0,)"
                           R"("stokes":[1.0,-0.5,0.25,0.125],"stokes_reference":[0.0,1.0,0.0]}]})"
                           "\n");
}

TEST(TraceFiles, PathEventsNameMediaAndWriteNullForNoShapeOrNoReflectance) {
    const std::vector<Medium> media{{"air", 1.0, {}, {}, 0.0}, {"water", 1.333, {}, {}, 0.0}};
    PhotonPath path;
    path.photon = 4;
    path.source = 1;
    path.wavelengthNm = 486.125;
    path.fate = PhotonFate::Lost;
    Event emit;
    emit.direction = Direction(0, 0, 1);
    Event refract = emit;
    refract.type = EventType::Refract;
    refract.shape = 7;
    refract.to = 1;
    refract.reflectance = 0.25;
    refract.weight = 0.5;
    Event lost = refract;
    lost.type = EventType::Lost;
    lost.from = 1;
    lost.lostReason = LostReason::MediumMismatch;
    path.events = {emit, refract, lost};
    std::ostringstream jsonl;
    writePathsJsonl({path}, media, jsonl);
    EXPECT_EQ(jsonl.str(),
              R"({"photon":4,"source":1,"wavelength_nm":486.125,"fate":"lost","events":[)"
              R"({"type":"emit","position":[0.0,0.0,0.0],"direction":[0.0,0.0,1.0],"shape":null,)"
              R"("medium_from":"air","medium_to":"air","R":null,"weight":1.0},)"
              R"({"type":"refract","position":[0.0,0.0,0.0],"direction":[0.0,0.0,1.0],"shape":7,)"
              R"("medium_from":"air","medium_to":"water","R":0.25,"weight":0.5},)"
              R"({"type":"lost","position":[0.0,0.0,0.0],"direction":[0.0,0.0,1.0],"shape":7,)"
              R"("medium_from":"water","medium_to":"water","R":0.25,"weight":0.5,"reason":"medium_mismatch"}]})"
              "\n");
}

}  // namespace
}  // namespace dropscope
