// `dropscope trace`, run in-process: the three files, their consistency, and bad input.
#include "app/CliRun.hpp"
#include "cli/Cli.hpp"
#include "optics/Diffraction.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using test::CliRun;
using test::expectOneLineFailure;
using test::runDropscope;

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Three shares of one count, each correctly rounded, add up to 1 within 3 half-ulps.
constexpr double kShareSumRounding = 4 * std::numeric_limits<double>::epsilon();
// fraction_per_sr is fraction / (2 pi (cos lo - cos hi)) with libm cosines (within an ulp or two):
// relative rounding of a handful of operations, and of summing <= 1e3 bins.
constexpr double kAngularRounding = 1e-12;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kDefaultScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";
const std::string kSingleRay = kDataDir + "/scenes/single_ray.json";  // one ray, no shapes
const std::string kNoSources = kDataDir + "/scenes/no_sources.json";

// A row of angular.csv; the Stokes columns NaN when the file has none (--polarisation none).
struct AngularRow {
    double lo, hi, fraction, perSteradian;
    double q = std::nan(""), u = std::nan(""), v = std::nan(""), dolp = std::nan("");
};

const std::string kAngularHeader = "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr";
const std::string kStokesColumns = ",stokes_q,stokes_u,stokes_v,dolp";

class TraceCommand : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::freshTestDirectory("trace"); }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // `dropscope trace SCENE --photons N ARGUMENTS... --out DIR/out`
    CliRun trace(const std::string& scene, const std::string& photons, std::vector<std::string> arguments = {},
                 const std::string& out = "out") const {
        std::vector<std::string> all{"trace", scene, "--photons", photons};
        all.insert(all.end(), arguments.begin(), arguments.end());
        all.insert(all.end(), {"--out", path(out)});
        return runDropscope(all);
    }

    static std::string read(const std::string& file) {
        std::ifstream in(file);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    static std::vector<std::string> lines(const std::string& file) {
        std::istringstream text(read(file));
        std::vector<std::string> result;
        for (std::string line; std::getline(text, line);) result.push_back(line);
        return result;
    }
    Json summary(const std::string& out = "out") const { return Json::parse(read(path(out + "/summary.json"))); }
    // angular.csv, with the Stokes columns (the default, --polarisation stokes) or without them.
    std::vector<AngularRow> angular(const std::string& out = "out", bool stokes = true) const {
        std::vector<std::string> rows = lines(path(out + "/angular.csv"));
        EXPECT_EQ(rows.empty() ? "" : rows.front(), kAngularHeader + (stokes ? kStokesColumns : ""));
        std::vector<AngularRow> result;
        for (std::size_t i = 1; i < rows.size(); ++i) {
            AngularRow row{};
            char comma = 0;
            std::istringstream fields(rows[i]);
            fields >> row.lo >> comma >> row.hi >> comma >> row.fraction >> comma >> row.perSteradian;
            if (stokes) fields >> comma >> row.q >> comma >> row.u >> comma >> row.v >> comma >> row.dolp;
            EXPECT_TRUE(fields && fields.peek() == EOF) << rows[i];
            result.push_back(row);
        }
        return result;
    }

    fs::path dir_;
};

std::vector<std::string> keysOf(const Json& object) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : object.items()) keys.push_back(key);
    return keys;
}

TEST_F(TraceCommand, WritesTheFourFilesWithTheDocumentedKeys) {
    const CliRun run = trace(kDefaultScene, "20000", {"--paths", "3", "--bins", "36", "--seed", "9"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_EQ(run.err, "");  // no progress line: err is not a terminal
    EXPECT_NE(run.out.find("trace: 20000 photons"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(path("out")), std::string::npos) << run.out;

    const Json s = summary();
    EXPECT_EQ(keysOf(s), (std::vector<std::string>{"photons",
                                                   "seed",
                                                   "ranks",
                                                   "threads",
                                                   "seconds",
                                                   "fractions",
                                                   "events",
                                                   "photons_requested",
                                                   "partial",
                                                   "scene",
                                                   "bins",
                                                   "fresnel",
                                                   "polarisation",
                                                   "diffraction",
                                                   "max_events",
                                                   "paths",
                                                   "counts",
                                                   "lost_reasons",
                                                   "lost_warning",
                                                   "max_lost",
                                                   "sources",
                                                   "wavelength_nm",
                                                   "wavelength_bins",
                                                   "spectra",
                                                   "budget",
                                                   "version"}));
    EXPECT_TRUE(s["lost_warning"].is_null());  // nothing lost: no warning, no first_lost, nothing on stderr
    EXPECT_TRUE(s["max_lost"].is_null());
    EXPECT_EQ(s["version"], "0.1.0");
    EXPECT_EQ(keysOf(s["fractions"]),
              (std::vector<std::string>{"escaped", "absorbed", "lost", "unscattered", "detected"}));
    EXPECT_EQ(keysOf(s["counts"]),
              (std::vector<std::string>{"escaped", "absorbed", "lost", "unscattered", "detected"}));
    EXPECT_EQ(keysOf(s["budget"]), (std::vector<std::string>{"photons", "escaped", "absorbed", "detected", "lost"}));
    EXPECT_EQ(keysOf(s["events"]), (std::vector<std::string>{"reflect", "refract", "tir", "absorb", "diffract"}));
    EXPECT_EQ(keysOf(s["lost_reasons"]),
              (std::vector<std::string>{"event_cap", "undefined_normal", "medium_mismatch", "no_exit"}));
    EXPECT_EQ(s["wavelength_nm"], 532.0);
    EXPECT_EQ(s["wavelength_bins"], 1);
    EXPECT_EQ(s["spectra"], Json::parse(R"({"0": {"spectrum": "scene", "lo_nm": 532.0, "hi_nm": 532.0, "lines": 1,
                                             "divergence_deg": 0.0}})"));
    EXPECT_EQ(s["photons"], 20000);
    EXPECT_EQ(s["photons_requested"], 20000);
    EXPECT_EQ(s["partial"], false);
    EXPECT_EQ(s["seed"], 9);
    EXPECT_EQ(s["scene"], kDefaultScene);
    EXPECT_EQ(s["bins"], 36);
    EXPECT_EQ(s["fresnel"], "exact");
    EXPECT_EQ(s["polarisation"], "stokes");
    EXPECT_EQ(s["max_events"], 10000);
    EXPECT_EQ(s["paths"], 3);
    EXPECT_EQ(s["sources"], 1);
    EXPECT_GE(s["threads"].get<int>(), 1);
    EXPECT_EQ(s["ranks"], 1);  // not started by mpirun
    EXPECT_GT(s["events"]["refract"].get<std::uint64_t>(), 0u);

    const std::vector<AngularRow> rows = angular();
    ASSERT_EQ(rows.size(), 36u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].lo, 5.0 * static_cast<double>(i));
        EXPECT_EQ(rows[i].hi, 5.0 * static_cast<double>(i + 1));
    }
    EXPECT_EQ(lines(path("out/paths.jsonl")).size(), 3u);
}

// A pencil aimed at a glass block's vertical edge (no normal there: every such photon is lost) beside a beam
// that crosses a face: half the photons are lost.
const std::string kEdgeScene = kDataDir + "/scenes/pencil_at_box_edge.json";
const std::string kEdgeWarning =
    "dropscope: warning: lost 50 % of the photons (1000 of 2000), mostly at box edges or vertices, where a surface "
    "has no normal (undefined_normal: 1000); the first, photon 0, on shapes[0]: box \"block\" at (-1, -1, 0), "
    "undefined_normal\n";

TEST_F(TraceCommand, LostPhotonsAreWarnedOnStderrAndInTheSummary) {
    const CliRun run = trace(kEdgeScene, "2000", {"--threads", "2"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_EQ(run.err, kEdgeWarning);
    const Json s = summary();
    EXPECT_EQ(s["counts"]["lost"], 1000);
    EXPECT_EQ(s["lost_warning"], kEdgeWarning.substr(20, kEdgeWarning.size() - 21));
    EXPECT_EQ(s["first_lost"],
              Json::parse(
                  R"({"photon": 0, "reason": "undefined_normal", "shape": 0, "shape_label": "shapes[0]: box \"block\"",
                       "x": -1.0, "y": -1.0, "z": 0.0})"));
    EXPECT_TRUE(s["max_lost"].is_null());
}

TEST_F(TraceCommand, MaxLostExitsFourAfterWritingEveryFile) {
    const CliRun over = trace(kEdgeScene, "2000", {"--max-lost", "0.49"});
    EXPECT_EQ(over.status, kExitTooManyLost);
    EXPECT_EQ(over.err, kEdgeWarning + "dropscope: lost share 0.5 is above --max-lost 0.49 (results written)\n");
    for (const char* file : {"summary.json", "angular.csv", "angular_spectral.csv", "paths.jsonl", "results.h5"}) {
        EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / file)) << file;
    }
    EXPECT_EQ(summary()["max_lost"], 0.49);
    const CliRun within = trace(kEdgeScene, "2000", {"--max-lost", "0.5"}, "within");
    EXPECT_EQ(within.status, kExitSuccess);
    EXPECT_EQ(within.err, kEdgeWarning);
    test::expectOneLineFailure(trace(kEdgeScene, "2000", {"--max-lost", "1.5"}, "bad"));
    EXPECT_FALSE(fs::exists(dir_ / "bad"));
    const CliRun nan = trace(kEdgeScene, "2000", {"--max-lost", "nan"}, "bad");  // would never be exceeded
    test::expectOneLineFailure(nan);
    EXPECT_EQ(nan.err.rfind("--max-lost: must be a number from 0 to 1", 0), 0u) << nan.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

// The first lost photon is the lowest index whatever the threads: the summary is the same on 1 and 3 threads.
TEST_F(TraceCommand, TheLossSummaryIsTheSameForAnyThreadCount) {
    ASSERT_EQ(trace(kEdgeScene, "3001", {"--threads", "1"}, "one").status, kExitSuccess);
    ASSERT_EQ(trace(kEdgeScene, "3001", {"--threads", "3"}, "three").status, kExitSuccess);
    Json one = summary("one");
    Json three = summary("three");
    for (Json* s : {&one, &three}) {
        s->erase("seconds");
        s->erase("threads");
    }
    EXPECT_EQ(one, three);
    EXPECT_EQ(one["first_lost"]["photon"], 0);
    EXPECT_EQ(one["counts"]["lost"], 1501);
}

TEST_F(TraceCommand, CountsAddUpAndFractionsAreTheirShares) {
    ASSERT_EQ(trace(kDefaultScene, "20000", {"--max-events", "3"}).status, kExitSuccess);  // some photons lost
    const Json s = summary();
    const Json& counts = s["counts"];
    const auto photons = s["photons"].get<std::uint64_t>();
    EXPECT_EQ(counts["escaped"].get<std::uint64_t>() + counts["absorbed"].get<std::uint64_t>() +
                  counts["lost"].get<std::uint64_t>(),
              photons);
    EXPECT_GT(counts["lost"].get<std::uint64_t>(), 0u);
    std::uint64_t lostForAReason = 0;
    for (const auto& [reason, count] : s["lost_reasons"].items()) lostForAReason += count.get<std::uint64_t>();
    EXPECT_EQ(lostForAReason, counts["lost"].get<std::uint64_t>());
    EXPECT_EQ(s["lost_reasons"]["event_cap"], counts["lost"]);  // a cap of 3 events is all that loses them here
    double total = 0.0;
    for (const char* fate : {"escaped", "absorbed", "lost", "unscattered"}) {
        const double expected = counts[fate].get<double>() / static_cast<double>(photons);
        EXPECT_EQ(s["fractions"][fate].get<double>(), expected) << fate;
        if (std::string(fate) != "unscattered") total += expected;
    }
    EXPECT_NEAR(total, 1.0, kShareSumRounding);
}

TEST_F(TraceCommand, AngularFractionsSumToTheEscapedShareOverTheirSolidAngles) {
    ASSERT_EQ(trace(kDefaultScene, "20000", {"--bins", "50"}).status, kExitSuccess);
    const Json s = summary();
    double sum = 0.0;
    for (const AngularRow& row : angular()) {
        sum += row.fraction;
        const double lo = row.lo * std::numbers::pi / 180.0;
        const double hi = row.hi * std::numbers::pi / 180.0;
        const double solidAngle = 2.0 * std::numbers::pi * (std::cos(lo) - std::cos(hi));
        EXPECT_NEAR(row.perSteradian * solidAngle, row.fraction, kAngularRounding * row.fraction) << row.lo;
    }
    EXPECT_NEAR(sum, s["fractions"]["escaped"].get<double>(), kAngularRounding);
    EXPECT_GT(sum, 0.9);
}

TEST_F(TraceCommand, SingleRayWithoutShapesEscapesUnscatteredInTheFirstBin) {
    ASSERT_EQ(trace(kSingleRay, "1000", {"--bins", "10"}).status, kExitSuccess);
    const Json s = summary();
    EXPECT_EQ(s["fractions"]["escaped"], 1.0);
    EXPECT_EQ(s["fractions"]["unscattered"], 1.0);
    EXPECT_EQ(s["counts"]["unscattered"], 1000);
    const std::vector<AngularRow> rows = angular();
    ASSERT_EQ(rows.size(), 10u);
    EXPECT_EQ(rows[0].fraction, 1.0);
    for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i].fraction, 0.0) << i;
}

TEST_F(TraceCommand, ThreadCountChangesNothingButThreadsAndSeconds) {
    ASSERT_EQ(trace(kDefaultScene, "30000", {"--threads", "1", "--paths", "20"}, "one").status, kExitSuccess);
    ASSERT_EQ(trace(kDefaultScene, "30000", {"--threads", "2", "--paths", "20"}, "two").status, kExitSuccess);
    Json one = summary("one");
    Json two = summary("two");
    EXPECT_EQ(one["threads"], 1);
    EXPECT_EQ(two["threads"], 2);
    for (Json* s : {&one, &two}) {
        s->erase("threads");
        s->erase("seconds");
    }
    EXPECT_EQ(one, two);
    EXPECT_EQ(read(path("one/angular.csv")), read(path("two/angular.csv")));
    EXPECT_EQ(read(path("one/paths.jsonl")), read(path("two/paths.jsonl")));
}

TEST_F(TraceCommand, PathsHoldTheFirstKPhotonsFromEmissionToTheirFate) {
    ASSERT_EQ(trace(kDefaultScene, "2000", {"--paths", "25", "--max-events", "4"}).status, kExitSuccess);
    const std::vector<std::string> jsonLines = lines(path("out/paths.jsonl"));
    ASSERT_EQ(jsonLines.size(), 25u);
    const std::vector<std::string> eventKeys{"type",        "position",  "direction", "shape",
                                             "medium_from", "medium_to", "R",         "weight"};
    const std::vector<std::string> stokesKeys{"stokes", "stokes_reference"};
    for (std::size_t i = 0; i < jsonLines.size(); ++i) {
        SCOPED_TRACE(jsonLines[i]);
        const Json photon = Json::parse(jsonLines[i]);
        EXPECT_EQ(keysOf(photon), (std::vector<std::string>{"photon", "source", "wavelength_nm", "fate", "events"}));
        EXPECT_EQ(photon["photon"], i);
        EXPECT_EQ(photon["source"], 0);
        EXPECT_EQ(photon["wavelength_nm"], 532.0);  // the default scene's wavelength_nm, no spectrum
        const Json& events = photon["events"];
        ASSERT_GE(events.size(), 2u);
        EXPECT_EQ(events.front()["type"], "emit");
        EXPECT_TRUE(events.front()["R"].is_null());
        EXPECT_TRUE(events.front()["shape"].is_null());
        EXPECT_EQ(events.front()["medium_from"], "air");
        const Json& last = events.back();
        const std::string fate = photon["fate"];
        const std::string lastType = fate == "escaped" ? "escape" : fate == "absorbed" ? "absorb" : "lost";
        EXPECT_EQ(last["type"], lastType);
        for (const Json& event : events) {
            std::vector<std::string> keys = eventKeys;
            if (event["type"] == "lost") keys.push_back("reason");
            keys.insert(keys.end(), stokesKeys.begin(), stokesKeys.end());
            EXPECT_EQ(keysOf(event), keys);
            EXPECT_EQ(event["position"].size(), 3u);
            EXPECT_EQ(event["direction"].size(), 3u);
            // The light after the event: I is the photon's weight, the reference a unit vector across its path.
            ASSERT_EQ(event["stokes"].size(), 4u);
            EXPECT_NEAR(event["stokes"][0].get<double>(), 1.0, 1e-15);
            double reference = 0.0, across = 0.0;
            for (int k = 0; k < 3; ++k) {
                reference += std::pow(event["stokes_reference"][k].get<double>(), 2);
                across += event["stokes_reference"][k].get<double>() * event["direction"][k].get<double>();
            }
            EXPECT_NEAR(reference, 1.0, 1e-14);
            EXPECT_NEAR(across, 0.0, 1e-14);
        }
        if (fate == "lost") {
            EXPECT_EQ(last["reason"], "event_cap");
        }
    }
}

TEST_F(TraceCommand, PolarisationNoneKeepsTheFilesOfTheUnpolarisedModel) {
    ASSERT_EQ(trace(kDefaultScene, "2000", {"--polarisation", "none", "--paths", "3", "--bins", "12"}).status,
              kExitSuccess);
    EXPECT_EQ(summary()["polarisation"], "none");
    EXPECT_EQ(angular("out", false).size(), 12u);
    for (const std::string& line : lines(path("out/paths.jsonl"))) {
        const Json photon = Json::parse(line);
        for (const Json& event : photon["events"]) EXPECT_FALSE(event.contains("stokes")) << line;
    }
}

TEST_F(TraceCommand, StokesColumnsAreSharesOfThePhotonsAndDolpTheirRatio) {
    ASSERT_EQ(trace(kDefaultScene, "20000", {"--bins", "18"}).status, kExitSuccess);
    for (const AngularRow& row : angular()) {
        SCOPED_TRACE(row.lo);
        // Each photon's |Q|, |U|, |V| <= I = 1, so a bin's sums are at most its fraction.
        EXPECT_LE(std::hypot(row.q, row.u, row.v), row.fraction * (1 + 1e-12));
        EXPECT_NEAR(row.dolp, row.fraction > 0 ? std::hypot(row.q, row.u) / row.fraction : 0.0, 1e-15);
    }
    // Unpolarised light scattered by water drops and a glass cell is polarised across the scattering plane
    // inside the primary bow (-Q > 0 in the 140-150 and 150-160 degree bins).
    const std::vector<AngularRow> rows = angular();
    EXPECT_LT(rows[14].q + rows[15].q, 0.0);
}

TEST_F(TraceCommand, SchlickTracesWithoutPolarisationUnlessStokesIsAsked) {
    ASSERT_EQ(trace(kDefaultScene, "500", {"--fresnel", "schlick"}).status, kExitSuccess);
    EXPECT_EQ(summary()["polarisation"], "none");
    const CliRun run = trace(kDefaultScene, "500", {"--fresnel", "schlick", "--polarisation", "stokes"}, "refused");
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, "--polarisation stokes: needs --fresnel exact (Schlick's approximation is unpolarised)\n");
    EXPECT_FALSE(fs::exists(path("refused")));
}

TEST_F(TraceCommand, PathsBeyondThePhotonsAreClamped) {
    ASSERT_EQ(trace(kSingleRay, "5", {"--paths", "1000"}).status, kExitSuccess);
    EXPECT_EQ(lines(path("out/paths.jsonl")).size(), 5u);
    EXPECT_EQ(summary()["paths"], 5);
}

TEST_F(TraceCommand, OptionsAreRecordedAndScientificCountsAccepted) {
    ASSERT_EQ(trace(kDefaultScene, "2e3", {"--fresnel", "schlick", "--max-events", "500", "--threads", "1"}).status,
              kExitSuccess);
    const Json s = summary();
    EXPECT_EQ(s["photons"], 2000);
    EXPECT_EQ(s["fresnel"], "schlick");
    EXPECT_EQ(s["max_events"], 500);
    EXPECT_EQ(s["threads"], 1);
    EXPECT_EQ(s["bins"], 180);
    EXPECT_EQ(s["seed"], 1);
    EXPECT_EQ(s["paths"], 0);
    EXPECT_EQ(read(path("out/paths.jsonl")), "");
}

TEST_F(TraceCommand, FresnelModelChangesTheReflectance) {
    ASSERT_EQ(trace(kDefaultScene, "3000", {"--fresnel", "exact"}, "exact").status, kExitSuccess);
    ASSERT_EQ(trace(kDefaultScene, "3000", {"--fresnel", "schlick"}, "schlick").status, kExitSuccess);
    EXPECT_NE(summary("exact")["events"], summary("schlick")["events"]);
}

TEST_F(TraceCommand, BadInputExitsTwoWithOneLineAndWritesNothing) {
    std::ofstream(path("file")) << "keep me\n";
    const struct {
        std::vector<std::string> arguments;
        std::string message;  // the start of the one line on stderr
    } cases[] = {
        {{"trace", kDefaultScene, "--out", path("out")}, "dropscope: --photons is required"},
        {{"trace", kDefaultScene, "--photons", "0", "--out", path("out")},
         "dropscope: --photons: must be a whole number >= 1"},
        {{"trace", kDefaultScene, "--photons", "-3", "--out", path("out")}, "dropscope: --photons: must be"},
        {{"trace", kDefaultScene, "--photons", "2.5", "--out", path("out")}, "dropscope: --photons: must be"},
        {{"trace", kDefaultScene, "--photons", "10", "--bins", "0", "--out", path("out")},
         "dropscope: --bins: must be"},
        {{"trace", kDefaultScene, "--photons", "10", "--bins", "100001", "--out", path("out")},
         "dropscope: --bins: must be a whole number from 1 to 100000"},
        {{"trace", kDefaultScene, "--photons", "1e12", "--paths", "1e12", "--out", path("out")},
         "dropscope: --paths: must be a whole number from 0 to 1000000"},
        {{"trace", kDefaultScene, "--photons", "10", "--threads", "-1", "--out", path("out")},
         "dropscope: --threads: must be"},
        {{"trace", kDefaultScene, "--photons", "10", "--max-events", "0", "--out", path("out")},
         "dropscope: --max-events: must be"},
        {{"trace", kDefaultScene, "--photons", "10", "--fresnel", "fast", "--out", path("out")},
         "dropscope: --fresnel: fast not in"},
        {{"trace", kDefaultScene, "--photons", "10", "--polarisation", "linear", "--out", path("out")},
         "dropscope: --polarisation: linear not in"},
        {{"trace", kDefaultScene, "--photons", "10", "--wavelength-bins", "0", "--out", path("out")},
         "dropscope: --wavelength-bins: must be a whole number from 1 to 10000"},
        {{"trace", kDefaultScene, "--photons", "10", "--wavelength-bins", "2", "--out", path("out")},
         "--wavelength-bins 2: the light has one wavelength: more than one wavelength bin needs a "
         "spectrum"},
        {{"trace", kDefaultScene, "--photons", "10", "--bins", "100000", "--wavelength-bins", "101", "--out",
          path("out")},
         "--bins 100000 with --wavelength-bins 101: more than 10000000 cells in angular_spectral.csv"},
        {{"trace", kDefaultScene, "--photons", "10"}, "dropscope: --out is required"},
        {{"trace", kDefaultScene, "--photons", "10", "--out", path("file")},
         path("file") + ": exists and is not a directory"},
        {{"trace", kDefaultScene, "--photons", "10", "--out", path("file/out")},
         path("file/out") + ": cannot create the output directory: "},
        {{"trace", kNoSources, "--photons", "10", "--out", path("out")},
         kNoSources + ": sources: the scene has no light sources to trace"},
        {{"trace", path("missing.json"), "--photons", "10", "--out", path("out")},
         path("missing.json") + ": no such file"},
        {{"trace", kDataDir + "/scenes/malformed.json", "--photons", "10", "--out", path("out")},
         kDataDir + "/scenes/malformed.json: line 4"},
    };
    for (const auto& [arguments, message] : cases) {
        SCOPED_TRACE(message);
        const CliRun run = runDropscope(arguments);
        expectOneLineFailure(run);
        EXPECT_TRUE(run.err.starts_with(message)) << run.err;
        EXPECT_FALSE(fs::exists(path("out")));
        EXPECT_EQ(read(path("file")), "keep me\n");
    }
}

TEST_F(TraceCommand, BadInputLeavesAnEarlierRunsFilesAlone) {
    ASSERT_EQ(trace(kSingleRay, "10").status, kExitSuccess);
    const std::string before = read(path("out/summary.json"));
    expectOneLineFailure(trace(kNoSources, "10"));
    expectOneLineFailure(trace(kSingleRay, "10", {"--bins", "0"}));
    EXPECT_EQ(read(path("out/summary.json")), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(path("out")), fs::directory_iterator()), 5);  // no leftovers
}

TEST_F(TraceCommand, AnOutputNameTakenByAFolderIsRefusedBeforeAnyFileIsReplaced) {
    ASSERT_EQ(trace(kSingleRay, "10").status, kExitSuccess);
    const std::string angular = read(path("out/angular.csv"));
    fs::remove(path("out/summary.json"));
    fs::create_directory(path("out/summary.json"));
    const CliRun run = trace(kSingleRay, "10", {"--bins", "7"});
    expectOneLineFailure(run);
    EXPECT_TRUE(run.err.starts_with(path("out/summary.json") + ": exists and is not a regular file")) << run.err;
    EXPECT_EQ(read(path("out/angular.csv")), angular);
}

const std::string kSunlitRainbow = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/sunlit-rainbow.json";

TEST_F(TraceCommand, WavelengthBinsSplitTheAngularDistributionByBand) {
    const CliRun run = trace(kSunlitRainbow, "20000", {"--bins", "36", "--wavelength-bins", "4", "--paths", "50"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_NE(run.out.find("angular_spectral.csv"), std::string::npos) << run.out;
    const Json s = summary();
    EXPECT_EQ(s["wavelength_nm"], 550.0);
    EXPECT_EQ(s["wavelength_bins"], 4);
    EXPECT_EQ(s["spectra"]["0"]["spectrum"], "sun");
    EXPECT_EQ(s["spectra"]["0"]["lo_nm"], 380.0);
    EXPECT_EQ(s["spectra"]["0"]["hi_nm"], 780.0);
    EXPECT_EQ(s["spectra"]["0"]["kelvin"], 5778.0);
    EXPECT_EQ(s["spectra"]["0"]["divergence_deg"], 0.266);

    const std::vector<std::string> rows = lines(path("out/angular_spectral.csv"));
    ASSERT_EQ(rows.size(), 1u + 4u * 36u);
    EXPECT_EQ(rows.front(), "wavelength_lo_nm,wavelength_hi_nm," + kAngularHeader + kStokesColumns);
    // K blocks of B rows; the K fractions of an angle add up to angular.csv's (exactly in counts: here within
    // the rounding of four divisions by the photon count)
    const std::vector<AngularRow> total = angular();
    std::vector<double> sum(36, 0.0);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::istringstream fields(rows[i]);
        double lo = 0, hi = 0, thetaLo = 0, thetaHi = 0, fraction = 0;
        char comma = 0;
        fields >> lo >> comma >> hi >> comma >> thetaLo >> comma >> thetaHi >> comma >> fraction;
        const std::size_t band = (i - 1) / 36, angle = (i - 1) % 36;
        EXPECT_EQ(lo, 380.0 + 100.0 * static_cast<double>(band)) << rows[i];
        EXPECT_EQ(hi, 380.0 + 100.0 * static_cast<double>(band + 1)) << rows[i];
        EXPECT_EQ(thetaLo, total[angle].lo);
        sum[angle] += fraction;
    }
    for (std::size_t angle = 0; angle < 36; ++angle) EXPECT_NEAR(sum[angle], total[angle].fraction, 1e-15);
    // each photon's wavelength, from the sun's 380-780 nm
    for (const std::string& line : lines(path("out/paths.jsonl"))) {
        const double wavelength = Json::parse(line)["wavelength_nm"];
        EXPECT_GE(wavelength, 380.0);
        EXPECT_LE(wavelength, 780.0);
    }
}

TEST_F(TraceCommand, OneWavelengthBinIsTheAngularTableWithItsEdges) {
    ASSERT_EQ(trace(kDefaultScene, "5000", {"--bins", "18"}).status, kExitSuccess);
    const std::vector<std::string> angular = lines(path("out/angular.csv"));
    const std::vector<std::string> spectral = lines(path("out/angular_spectral.csv"));
    ASSERT_EQ(spectral.size(), angular.size());
    for (std::size_t i = 1; i < angular.size(); ++i) EXPECT_EQ(spectral[i], "532,532," + angular[i]);
}

}  // namespace
}  // namespace dropscope

namespace dropscope {
namespace {

// A water drop in a beam with one detector of each kind (and an absorbing wall far behind), as JSON.
std::string detectorScene() {
    return R"({"dropscope": 1, "media": {"water": {"n": 1.333, "kappa": 1e-6}, "glass": {"n": 1.5, "sigma": 0.2}},
      "shapes": [{"type": "sphere", "name": "drop", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                 {"type": "sphere", "name": "bead, small", "center": [0, 0.2, 2.5], "radius": 0.3, "medium": "glass"}],
      "sources": [{"type": "beam", "origin": [0, 0, -4], "direction": [0, 0, 1], "radius": 1.2}],
      "detectors": [
        {"type": "far_field", "name": "sky", "look": [0, 0, 1], "up": [0, 1, 0], "projection": "equidistant",
         "fov_deg": 110, "pixels": [24, 20], "record": 5},
        {"type": "plane", "name": "screen", "center": [0, 0, 4], "normal": [0, 0, -1], "up": [0, 1, 0],
         "size": [6, 4], "pixels": [12, 8], "record": 4},
        {"type": "plane", "name": "wall", "center": [0, 0, 8], "normal": [0, 0, -1], "up": [0, 1, 0],
         "size": [40, 40], "pixels": [4, 4], "side": "front", "absorbing": true},
        {"type": "shape_absorption", "name": "absorbed", "record": 3}]})";
}

std::vector<double> csvColumn(const std::vector<std::string>& rows, std::size_t column) {
    std::vector<double> values;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::istringstream fields(rows[i]);
        std::string cell;
        for (std::size_t c = 0; c <= column; ++c) std::getline(fields, cell, ',');
        values.push_back(std::stod(cell));
    }
    return values;
}

double sum(const std::vector<double>& values) {
    double total = 0.0;
    for (double v : values) total += v;
    return total;
}

// A water drop of radius 0.05 mm in a beam of radius 0.08 mm: with diffraction a ring as large as the drop's outline
// diffracts (0.05^2 / 0.08^2 of the photons), into angles of about lambda / (2 a), the "diffraction" column.
TEST_F(TraceCommand, FraunhoferDiffractionDiffractsTheRingAroundTheDrop) {
    std::ofstream(path("scene.json")) << R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
        "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.05, "medium": "water"}],
        "sources": [{"type": "beam", "origin": [0, 0, -1], "direction": [0, 0, 1], "radius": 0.08}]})";
    const CliRun run = trace(path("scene.json"), "20000", {"--orders", "--diffraction", "fraunhofer", "--bins", "90"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const Json s = summary();
    EXPECT_EQ(s["diffraction"], "fraunhofer");
    const double ring = 0.05 * 0.05 / (0.08 * 0.08);
    EXPECT_NEAR(s["events"]["diffract"].get<double>() / 20000.0, ring, 5.0 * std::sqrt(ring * (1 - ring) / 20000.0));
    EXPECT_NEAR(s["fractions"]["unscattered"].get<double>(), 1.0 - 2.0 * ring, 0.02);
    const std::vector<std::string> orders = lines(path("out/angular_orders.csv"));
    EXPECT_EQ(orders.front(), "theta_lo_deg,theta_hi_deg,p0,p1,p2,p3,p4,p5_plus,multiple,diffraction");
    const std::vector<double> diffracted = csvColumn(orders, 9);
    // The first 2-degree bin holds the Airy pattern's encircled energy out to u = x sin(2 degrees), x = 590.5 (the
    // first dark ring is at 0.37 degrees; the tail 1 - F ~ 2 / (pi u) leaves 3 % beyond).
    const double x = 2.0 * std::numbers::pi * 0.05 / 532e-6;
    const double inFirstBin =
        airyEncircledEnergy(x * std::sin(2.0 * std::numbers::pi / 180.0)) / airyEncircledEnergy(x);
    EXPECT_NEAR(diffracted[0] / sum(diffracted), inFirstBin, 0.01);

    const CliRun bad = trace(path("scene.json"), "10", {"--diffraction", "mie"}, "bad");
    EXPECT_EQ(bad.status, kExitBadInput);
    EXPECT_NE(bad.err.find("--diffraction"), std::string::npos) << bad.err;
}

TEST_F(TraceCommand, DetectorsWriteTheirFilesAndTheBudgetAddsUp) {
    std::ofstream(path("scene.json")) << detectorScene();
    const CliRun run = trace(path("scene.json"), "20000", {"--orders", "--bins", "90"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    for (const char* name :
         {"summary.json", "angular.csv", "angular_spectral.csv", "angular_orders.csv", "detector-sky.csv",
          "detector-sky.png", "detector-sky-records.csv", "detector-screen.csv", "detector-screen-records.csv",
          "detector-wall.csv", "detector-absorbed.csv", "detector-absorbed-records.csv", "paths.jsonl", "results.h5"}) {
        EXPECT_TRUE(fs::is_regular_file(path(std::string("out/") + name))) << name;
    }
    EXPECT_FALSE(fs::exists(path("out/detector-wall-records.csv")));
    EXPECT_TRUE(read(path("out/detector-sky.png")).starts_with("\x89PNG"));
    EXPECT_TRUE(read(path("out/results.h5")).starts_with("\x89HDF\r\n\x1a\n"));

    const Json s = summary();
    const auto photons = s["photons"].get<std::uint64_t>();
    const Json& budget = s["budget"];
    EXPECT_EQ(budget["photons"], photons);
    const auto count = [](const Json& entry) { return entry["count"].get<std::uint64_t>(); };
    EXPECT_EQ(count(budget["escaped"]) + count(budget["absorbed"]) + count(budget["detected"]) + count(budget["lost"]),
              photons);
    EXPECT_EQ(count(budget["escaped"]["far_field"]["sky"]) + count(budget["escaped"]["elsewhere"]),
              count(budget["escaped"]));
    EXPECT_EQ(count(budget["absorbed"]["by_medium"]["water"]) + count(budget["absorbed"]["by_medium"]["glass"]) +
                  count(budget["absorbed"]["by_medium"]["vacuum"]),
              count(budget["absorbed"]));
    EXPECT_GT(count(budget["absorbed"]["by_medium"]["glass"]), 0u);
    EXPECT_EQ(count(budget["detected"]["by_detector"]["wall"]), count(budget["detected"]));
    EXPECT_EQ(s["counts"]["detected"], count(budget["detected"]));
    EXPECT_GT(count(budget["detected"]), photons / 2);  // most light goes on through and ends on the wall
    EXPECT_EQ(s["detectors"]["sky"]["hits"], count(budget["escaped"]["far_field"]["sky"]));
    EXPECT_EQ(s["detectors"]["wall"]["hits"], count(budget["detected"]));

    // Tables: headers, one row per pixel, shares adding up to the summary's.
    const std::vector<std::string> sky = lines(path("out/detector-sky.csv"));
    EXPECT_EQ(sky.front(),
              "ix,iy,theta_deg,azimuth_deg,fraction,radiance,stokes_q,stokes_u,stokes_v,cie_x,cie_y,cie_z");
    EXPECT_EQ(sky.size(), 1u + 24 * 20);
    EXPECT_EQ(sky[1].substr(0, 4), "0,0,");
    EXPECT_EQ(sky[25].substr(0, 4), "0,1,");  // iy outer, ix inner
    EXPECT_NEAR(sum(csvColumn(sky, 4)), s["detectors"]["sky"]["fraction"].get<double>(), 1e-12);
    const std::vector<std::string> screen = lines(path("out/detector-screen.csv"));
    EXPECT_EQ(screen.front(), "ix,iy,u,v,fraction,irradiance,stokes_q,stokes_u,stokes_v");
    EXPECT_EQ(screen.size(), 1u + 12 * 8);
    EXPECT_NEAR(sum(csvColumn(screen, 4)), s["detectors"]["screen"]["fraction"].get<double>(), 1e-12);
    const std::vector<std::string> absorbed = lines(path("out/detector-absorbed.csv"));
    ASSERT_EQ(absorbed.size(), 3u);
    EXPECT_EQ(absorbed[0], "shape,name,medium,fraction");
    EXPECT_TRUE(absorbed[1].starts_with("0,drop,water,")) << absorbed[1];
    EXPECT_TRUE(absorbed[2].starts_with("1,\"bead, small\",glass,")) << absorbed[2];
    const double inShapes = std::stod(absorbed[1].substr(absorbed[1].rfind(',') + 1)) +
                            std::stod(absorbed[2].substr(absorbed[2].rfind(',') + 1));
    EXPECT_NEAR(inShapes + s["detectors"]["absorbed"]["ambient"].get<double>(),
                s["fractions"]["absorbed"].get<double>(), kShareSumRounding);
    EXPECT_EQ(lines(path("out/detector-screen-records.csv")).front(),
              "photon,x,y,z,dx,dy,dz,weight,wavelength_nm,stokes_i,stokes_q,stokes_u,stokes_v,events,path_length");
    EXPECT_EQ(lines(path("out/detector-screen-records.csv")).size(), 5u);
    EXPECT_EQ(lines(path("out/detector-absorbed-records.csv")).front(),
              "photon,x,y,z,dx,dy,dz,weight,wavelength_nm,events,path_length");

    // Orders: p columns add up to single_scattering; single + multiple + unscattered = escaped.
    const std::vector<std::string> orders = lines(path("out/angular_orders.csv"));
    EXPECT_EQ(orders.front(), "theta_lo_deg,theta_hi_deg,p0,p1,p2,p3,p4,p5_plus,multiple");
    EXPECT_EQ(orders.size(), 91u);
    double single = 0.0;
    for (std::size_t c = 2; c < 8; ++c) single += sum(csvColumn(orders, c));
    EXPECT_NEAR(single, s["single_scattering"].get<double>(), 1e-12);
    EXPECT_NEAR(sum(csvColumn(orders, 8)), s["multiple_scattering"].get<double>(), 1e-12);
    EXPECT_GT(s["multiple_scattering"].get<double>(), 0.0);  // drop then bead
    EXPECT_NEAR(s["single_scattering"].get<double>() + s["multiple_scattering"].get<double>() +
                    s["fractions"]["unscattered"].get<double>(),
                s["fractions"]["escaped"].get<double>(), 1e-12);
}

TEST_F(TraceCommand, DetectorFilesAreTheSameForAnyThreadCount) {
    std::ofstream(path("scene.json")) << detectorScene();
    ASSERT_EQ(trace(path("scene.json"), "20000", {"--orders", "--threads", "1"}, "one").status, kExitSuccess);
    ASSERT_EQ(trace(path("scene.json"), "20000", {"--orders", "--threads", "2"}, "two").status, kExitSuccess);
    std::size_t compared = 0;
    for (const auto& entry : fs::directory_iterator(path("one"))) {
        const std::string name = entry.path().filename().string();
        if (name == "summary.json") continue;
        EXPECT_EQ(read(entry.path().string()), read(path("two/" + name))) << name;
        ++compared;
    }
    EXPECT_GE(compared, 13u);  // results.h5 among them
    Json one = summary("one");
    Json two = summary("two");
    for (Json* s : {&one, &two}) {
        s->erase("threads");
        s->erase("seconds");
    }
    EXPECT_EQ(one, two);
}

TEST_F(TraceCommand, BadDetectorsExitTwoNamingTheirPlace) {
    std::ofstream(path("scene.json")) << R"({"dropscope": 1, "sources": [{"type": "ray", "origin": [0, 0, 0],
        "direction": [0, 0, 1]}], "detectors": [{"type": "far_field", "name": "sky", "look": [0, 0, 1],
        "up": [0, 0, 1], "fov_deg": 90, "pixels": [4, 4]}]})";
    const CliRun run = trace(path("scene.json"), "10");
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, path("scene.json") + ": detectors[0].up: up must not be along the look direction\n");
    EXPECT_FALSE(fs::exists(path("out")));

    // A detector's file name taken by a folder: refused before the run.
    std::ofstream(path("ok.json")) << R"({"dropscope": 1, "sources": [{"type": "ray", "origin": [0, 0, 0],
        "direction": [0, 0, 1]}], "detectors": [{"type": "shape_absorption", "name": "abs"}]})";
    fs::create_directories(path("out/detector-abs.csv"));
    const CliRun taken = trace(path("ok.json"), "10");
    expectOneLineFailure(taken);
    EXPECT_TRUE(taken.err.starts_with(path("out/detector-abs.csv") + ": exists and is not a regular file"))
        << taken.err;
    EXPECT_FALSE(fs::exists(path("out/summary.json")));
}

}  // namespace
}  // namespace dropscope
