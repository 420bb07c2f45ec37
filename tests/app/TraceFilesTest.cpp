// The writers behind `dropscope trace`, on results made by hand: corner cases a real run rarely hits.
#include "cli/TraceFiles.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace dropscope {
namespace {

using Json = nlohmann::json;

TEST(TraceFiles, NoPhotonTracedGivesNullFractionsAndAPartialSummary) {
    TraceResult result;
    result.tally = TraceTally(4);
    result.requested = 1000;
    result.partial = true;
    result.threads = 3;
    TraceRunInfo info{"scene.json", 2, {}};
    std::ostringstream summary;
    writeTraceSummary(result, info, summary);
    const Json s = Json::parse(summary.str());
    EXPECT_EQ(s["photons"], 0);
    EXPECT_EQ(s["photons_requested"], 1000);
    EXPECT_EQ(s["partial"], true);
    EXPECT_EQ(s["threads"], 3);
    EXPECT_EQ(s["sources"], 2);
    EXPECT_EQ(s["bins"], 4);
    for (const char* fate : {"escaped", "absorbed", "lost", "unscattered"}) EXPECT_TRUE(s["fractions"][fate].is_null());

    std::ostringstream csv;
    writeAngularCsv(result.tally, csv);
    EXPECT_EQ(csv.str(),
              "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr\n"
              "0,45,nan,nan\n45,90,nan,nan\n90,135,nan,nan\n135,180,nan,nan\n");
}

TEST(TraceFiles, AngularNumbersReadBackExactly) {
    TraceTally tally(7);
    tally.photons = 3;
    tally.angular[2] = 1;
    std::ostringstream csv;
    writeAngularCsv(tally, csv);
    std::istringstream rows(csv.str());
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

TEST(TraceFiles, PathEventsNameMediaAndWriteNullForNoShapeOrNoReflectance) {
    const std::vector<Medium> media{{"air", 1.0, {}, {}, 0.0}, {"water", 1.333, {}, {}, 0.0}};
    PhotonPath path;
    path.photon = 4;
    path.source = 1;
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
              R"({"photon":4,"source":1,"fate":"lost","events":[)"
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
