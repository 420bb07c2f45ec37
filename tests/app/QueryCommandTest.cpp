#include "app/CliRun.hpp"
#include "cli/Cli.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>

namespace dropscope {
namespace {

using test::CliRun;
using test::expectOneLineFailure;
using test::runDropscope;

namespace fs = std::filesystem;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kSourceDir = DROPSCOPE_SOURCE_DIR;
const std::string kOneSphere = kDataDir + "/scenes/one_sphere.json";  // r = 2 at (1, 2, 3)

class QueryCommand : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("dropscope-query-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path.string();
    }
    static std::string read(const std::string& path) {
        std::ifstream in(path);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

TEST_F(QueryCommand, HitsMatchClosedFormsAndMissesAreMinusOneNan) {
    const std::string rays = write("rays.csv",
                                   "ox,oy,oz,dx,dy,dz\n"
                                   "1,2,-10,0,0,2\n"  // along the axis: 13 - 2 = 11
                                   "1,2,3,1,0,0\n"    // from the centre: the radius
                                   "2,2,-10,0,0,1\n"  // 1 off the axis: 13 - sqrt(3)
                                   "9,9,9,1,0,0\n");  // a miss
    const CliRun run = runDropscope({"query", kOneSphere, "--rays", rays, "--out", path("hits.csv")});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    std::istringstream lines(read(path("hits.csv")));
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line, "ray,shape,distance");
    std::getline(lines, line);
    EXPECT_EQ(line, "0,0,11");
    std::getline(lines, line);
    EXPECT_EQ(line, "1,0,2");
    std::getline(lines, line);
    EXPECT_EQ(std::stod(line.substr(4)), 13.0 - std::sqrt(3.0)) << line;  // 17 digits read back exactly
    EXPECT_EQ(line.substr(0, 4), "2,0,");
    std::getline(lines, line);
    EXPECT_EQ(line, "3,-1,nan");
    EXPECT_FALSE(std::getline(lines, line));
    EXPECT_NE(run.err.find("query: 1 shapes, 4 rays, octree"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("rays/s"), std::string::npos);
}

// Scripts read the summary up to "rays/s" (bench/python_bench.py): its text stays, the I/O seconds come after.
TEST_F(QueryCommand, SummaryKeepsItsTextAndEndsWithReadAndWriteSeconds) {
    const std::string rays = write("rays.csv", "ox,oy,oz,dx,dy,dz\r\n1,2,-10,0,0,2\r\n\r\n9,9,9,1,0,0");
    const CliRun run = runDropscope({"query", kOneSphere, "--rays", rays, "--out", path("hits.csv")});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_EQ(read(path("hits.csv")), "ray,shape,distance\n0,0,11\n1,-1,nan\n");
    const std::regex summary(
        "query: 1 shapes, 2 rays, octree, build [0-9.]+ s, query [0-9.]+ s, [0-9]+ rays/s, read [0-9.]+ s, "
        "write [0-9.]+ s, 1 thread\n");
    EXPECT_TRUE(std::regex_match(run.err, summary)) << run.err;
}

// `count` rays as CSV, 17 digits: origins 3 N(0, 1) in each coordinate, directions N(0, 1); one draw per
// statement, so every compiler writes the same file.
std::string randomRays(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::ostringstream rays;
    rays << "ox,oy,oz,dx,dy,dz\n";
    rays.precision(17);
    for (int i = 0; i < count; ++i) {
        for (int k = 0; k < 6; ++k) {
            const double value = normal(rng);
            rays << (k < 3 ? 3.0 * value : value) << (k < 5 ? ',' : '\n');
        }
    }
    return rays.str();
}

TEST_F(QueryCommand, OctreeAndBruteForceWriteIdenticalFiles) {
    const std::string raysPath = write("rays.csv", randomRays(5, 3000));
    const std::string scene = kSourceDir + "/assets/scenes/default.json";
    ASSERT_EQ(runDropscope({"query", scene, "--rays", raysPath, "--out", path("octree.csv")}).status, kExitSuccess);
    ASSERT_EQ(runDropscope({"query", scene, "--rays", raysPath, "--out", path("brute.csv"), "--brute"}).status,
              kExitSuccess);
    const std::string octree = read(path("octree.csv"));
    EXPECT_EQ(octree, read(path("brute.csv")));
    std::istringstream lines(octree);
    std::string line;
    int rows = -1;  // the header
    int hits = 0;
    while (std::getline(lines, line)) {
        ++rows;
        hits += line.ends_with(",-1,nan") ? 0 : 1;
    }
    EXPECT_EQ(rows, 3000);
    EXPECT_GT(hits - 1, 100);  // the header line counted as a hit
}

// --threads shares the rays out; every thread count writes the same bytes, octree and brute force alike.
TEST_F(QueryCommand, EveryThreadCountWritesTheSameFile) {
    const std::string raysPath = write("rays.csv", randomRays(7, 20000));  // several chunks of 4096 rays
    const std::string scene = kSourceDir + "/assets/scenes/default.json";
    const CliRun one = runDropscope({"query", scene, "--rays", raysPath, "--out", path("one.csv")});
    ASSERT_EQ(one.status, kExitSuccess) << one.err;
    EXPECT_TRUE(one.err.ends_with(", 1 thread\n")) << one.err;
    const std::string expected = read(path("one.csv"));
    const CliRun three =
        runDropscope({"query", scene, "--rays", raysPath, "--out", path("three.csv"), "--threads", "3"});
    ASSERT_EQ(three.status, kExitSuccess) << three.err;
    EXPECT_TRUE(three.err.ends_with(", 3 threads\n")) << three.err;
    EXPECT_EQ(read(path("three.csv")), expected);
    ASSERT_EQ(runDropscope({"query", scene, "--rays", raysPath, "--out", path("all.csv"), "--threads", "0"}).status,
              kExitSuccess);
    EXPECT_EQ(read(path("all.csv")), expected);
    ASSERT_EQ(
        runDropscope({"query", scene, "--rays", raysPath, "--out", path("brute.csv"), "--brute", "--threads", "2"})
            .status,
        kExitSuccess);
    EXPECT_EQ(read(path("brute.csv")), expected);
    for (const char* bad : {"-1", "1.5", "many", "1025"}) {
        const CliRun run =
            runDropscope({"query", scene, "--rays", raysPath, "--out", path("bad.csv"), "--threads", bad});
        expectOneLineFailure(run);
        EXPECT_TRUE(run.err.starts_with("dropscope: --threads: must be a whole number from 0 to 1024")) << run.err;
        EXPECT_FALSE(fs::exists(path("bad.csv")));
    }
}

TEST_F(QueryCommand, MalformedLineNamesItsNumberAndWritesNothing) {
    const std::string rays = write("rays.csv", "ox,oy,oz,dx,dy,dz\n0,0,0,1,0,0\n0,0,zero,1,0,0\n");
    const CliRun run = runDropscope({"query", kOneSphere, "--rays", rays, "--out", path("hits.csv")});
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, rays + ":3: field 3 (oz) is not a number: \"zero\"\n");
    EXPECT_FALSE(fs::exists(path("hits.csv")));
}

TEST_F(QueryCommand, BadRayFilesAreRefused) {
    const std::pair<std::string, std::string> cases[] = {
        {"x,y,z\n", ":1: expected the header \"ox,oy,oz,dx,dy,dz\""},
        {"", ": empty file (expected the header \"ox,oy,oz,dx,dy,dz\")"},
        {"ox,oy,oz,dx,dy,dz\n1,2,3,0,0,0\n", ":2: direction (dx, dy, dz) is zero"},
        {"ox,oy,oz,dx,dy,dz\n1,2,3,0,0\n", ":2: expected 6 fields (ox,oy,oz,dx,dy,dz), got 5"},
        {"ox,oy,oz,dx,dy,dz\n1,2,3,0,0,1,7\n", ":2: more than 6 fields"},
        {"ox,oy,oz,dx,dy,dz\n1,2,3,nan,0,1\n", ":2: field 4 is not finite"},
    };
    for (const auto& [text, message] : cases) {
        const std::string rays = write("rays.csv", text);
        const CliRun run = runDropscope({"query", kOneSphere, "--rays", rays, "--out", path("hits.csv")});
        expectOneLineFailure(run);
        EXPECT_EQ(run.err, rays + message + "\n");
        EXPECT_FALSE(fs::exists(path("hits.csv")));
    }
}

TEST_F(QueryCommand, ExistingOutputSurvivesAFailedRun) {
    const std::string out = write("hits.csv", "keep me\n");
    const CliRun run = runDropscope({"query", kOneSphere, "--rays", path("missing.csv"), "--out", out});
    expectOneLineFailure(run);
    EXPECT_EQ(read(out), "keep me\n");
}

TEST_F(QueryCommand, MissingSceneOrUnwritableOutputIsBadInput) {
    const std::string rays = write("rays.csv", "ox,oy,oz,dx,dy,dz\n0,0,0,1,0,0\n");
    expectOneLineFailure(runDropscope({"query", path("none.json"), "--rays", rays, "--out", path("hits.csv")}));
    expectOneLineFailure(runDropscope({"query", kOneSphere, "--rays", rays, "--out", path("no/such/dir/hits.csv")}));
    expectOneLineFailure(runDropscope({"query", kOneSphere, "--rays", rays}));  // --out is required
}

}  // namespace
}  // namespace dropscope
