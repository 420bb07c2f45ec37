// `dropscope snapshot` run in-process: the PNG it writes, and every kind of bad input (exit 2, one line
// on stderr, no file written, an existing output left alone).
#include "app/CliRun.hpp"
#include "cli/Cli.hpp"
#include "snapshot/Image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace dropscope {
namespace {

using test::CliRun;
using test::expectOneLineFailure;
using test::runDropscope;

namespace fs = std::filesystem;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kOneSphere = kDataDir + "/scenes/one_sphere.json";  // r = 2 at (1, 2, 3), a ray source
const std::string kNoSources = kDataDir + "/scenes/no_sources.json";
const std::string kMalformed = kDataDir + "/scenes/malformed.json";

// CTest runs the tests of a fixture in parallel: one test's picture must not be another's "nothing written".
std::string perTestOutput(const std::string& stem) {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    return (fs::temp_directory_path() / (stem + "-" + test + "-" + std::to_string(::getpid()) + ".png")).string();
}

class SnapshotCommand : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("dropscope-snapshot-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static std::string read(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    // Exit 2, one line, and nothing left in the directory.
    void expectRejected(const std::vector<std::string>& arguments) const {
        SCOPED_TRACE(::testing::PrintToString(arguments));
        const CliRun run = runDropscope(arguments);
        expectOneLineFailure(run);
        EXPECT_TRUE(fs::is_empty(dir_)) << "a failed run left a file";
    }

    fs::path dir_;
};

TEST_F(SnapshotCommand, WritesAPngOfTheRequestedSize) {
    const std::string out = path("shot.png");
    const CliRun run = runDropscope({"snapshot", kOneSphere, "--out", out, "--width", "64", "--height", "48"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(run.out, "snapshot: 64x48 written to " + out + "\n");
    EXPECT_TRUE(read(out).starts_with("\x89PNG\r\n\x1a\n")) << "no PNG signature";
    const snapshot::Image image = snapshot::readPng(out);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
    // The droplet is drawn: the centre of a fitted view is not the background of the corner.
    EXPECT_FALSE(std::equal(image.pixel(32, 24), image.pixel(32, 24) + 3, image.pixel(0, 0)));
    EXPECT_EQ(fs::directory_iterator(dir_)->path(), fs::path(out)) << "only the PNG is left, no temporary file";
}

TEST_F(SnapshotCommand, CameraPathsAndOctreeOptionsAreAccepted) {
    const std::string out = path("shot.png");
    const CliRun run =
        runDropscope({"snapshot", kOneSphere, "--out",     out,     "--width",   "48", "--height",       "32",
                      "--eye",    "1,2,-12",  "--target",  "1,2,3", "--fov-deg", "30", "--octree-level", "0",
                      "--paths",  "3",        "--photons", "10",    "--seed",    "4"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_EQ(snapshot::readPng(out).width, 48);
}

TEST_F(SnapshotCommand, BadArgumentsExitTwoWithOneLineAndWriteNothing) {
    const std::string out = path("shot.png");
    expectRejected({"snapshot", kOneSphere});    // --out is required
    expectRejected({"snapshot", "--out", out});  // so is the scene
    expectRejected({"snapshot", kOneSphere, "--out", out, "--width", "0"});
    expectRejected({"snapshot", kOneSphere, "--out", out, "--height", "-3"});
    expectRejected({"snapshot", kOneSphere, "--out", out, "--width", "wide"});
    expectRejected({"snapshot", kOneSphere, "--out", out, "--fov-deg", "180"});
    expectRejected({"snapshot", kOneSphere, "--out", out, "--octree-level", "-1"});
    expectRejected({"snapshot", kOneSphere, "--out", out, "--unknown-flag"});
}

TEST_F(SnapshotCommand, BadPointsExitTwoNamingTheOption) {
    const std::string out = path("shot.png");
    for (const char* text : {"", "1,2", "1,2,3,4", "a,b,c", "1;2;3", "1,2,nan", "1,2,inf", "1,,2"}) {
        SCOPED_TRACE(text);
        const CliRun run = runDropscope({"snapshot", kOneSphere, "--out", out, "--eye", text});
        expectOneLineFailure(run);
        EXPECT_FALSE(fs::exists(out));
        EXPECT_TRUE(run.err.starts_with("--eye: expected three numbers x,y,z")) << run.err;
    }
    const CliRun run = runDropscope({"snapshot", kOneSphere, "--out", out, "--target", "0,0"});
    expectOneLineFailure(run);
    EXPECT_TRUE(run.err.starts_with("--target: ")) << run.err;
}

TEST_F(SnapshotCommand, EyeEqualToTargetIsBadInput) {
    const CliRun run =
        runDropscope({"snapshot", kOneSphere, "--out", path("shot.png"), "--eye", "1,2,3", "--target", "1,2,3"});
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, "--eye and --target must differ\n");
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(SnapshotCommand, BadScenesExitTwoNamingTheFile) {
    const std::string out = path("shot.png");
    const CliRun missing = runDropscope({"snapshot", path("none.json"), "--out", out});
    expectOneLineFailure(missing);
    EXPECT_NE(missing.err.find("none.json: "), std::string::npos) << missing.err;
    const CliRun malformed = runDropscope({"snapshot", kMalformed, "--out", out});
    expectOneLineFailure(malformed);
    EXPECT_NE(malformed.err.find("malformed.json: line 4"), std::string::npos) << malformed.err;
    const CliRun noSources = runDropscope({"snapshot", kNoSources, "--out", out, "--paths", "2"});
    expectOneLineFailure(noSources);
    EXPECT_NE(noSources.err.find("no_sources.json: sources: --paths needs a light source"), std::string::npos)
        << noSources.err;
    EXPECT_TRUE(fs::is_empty(dir_));
}

// README: an unusable output path is bad input (exit 2).
TEST_F(SnapshotCommand, UnusableOutputPathIsBadInput) {
    const CliRun run = runDropscope(
        {"snapshot", kOneSphere, "--out", path("no/such/dir/shot.png"), "--width", "32", "--height", "32"});
    expectOneLineFailure(run);
    EXPECT_NE(run.err.find("no/such/dir/shot.png"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(SnapshotCommand, ExistingOutputSurvivesAFailedRun) {
    const std::string out = path("shot.png");
    std::ofstream(out) << "keep me\n";
    expectOneLineFailure(runDropscope({"snapshot", kMalformed, "--out", out}));
    expectOneLineFailure(runDropscope({"snapshot", kNoSources, "--out", out, "--paths", "1"}));
    expectOneLineFailure(runDropscope({"snapshot", kOneSphere, "--out", out, "--eye", "0,0"}));
    EXPECT_EQ(read(out), "keep me\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << "a temporary file was left";
}

}  // namespace
}  // namespace dropscope

namespace dropscope {
namespace {

class SnapshotCamera : public ::testing::Test {
protected:
    std::string out = perTestOutput("dropscope-snapshot-camera");
    void TearDown() override { fs::remove(out); }
};

TEST_F(SnapshotCamera, AnEyeOnTheImpliedTargetIsBadInput) {
    // No view in the scene: the target is the scene's centre, (1, 2, 3) here.
    const CliRun run = runDropscope({"snapshot", kOneSphere, "--out", out, "--eye", "1,2,3"});
    expectOneLineFailure(run);
    EXPECT_TRUE(run.err.starts_with("the camera's eye coincides with its target")) << run.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(SnapshotCamera, LookingAlongUpStillGivesAPicture) {
    // Straight down on the sphere along -y, the default up: another up is taken, the sphere is centred.
    ASSERT_EQ(runDropscope({"snapshot", kOneSphere, "--out", out, "--eye", "1,12,3", "--width", "64", "--height", "48"})
                  .status,
              kExitSuccess);
    const snapshot::Image image = snapshot::readPng(out);
    const std::uint8_t* center = image.pixel(32, 24);
    const std::uint8_t* corner = image.pixel(1, 1);
    EXPECT_GT(center[2], corner[2] + 60);  // blue drop against the dark background
}

TEST_F(SnapshotCamera, PhotonCountsAreBounded) {
    expectOneLineFailure(runDropscope({"snapshot", kOneSphere, "--out", out, "--paths", "1", "--photons", "-1"}));
    expectOneLineFailure(
        runDropscope({"snapshot", kOneSphere, "--out", out, "--paths", "1", "--photons", "100000001"}));
    expectOneLineFailure(runDropscope({"snapshot", kOneSphere, "--out", out, "--paths", "1", "--seed", "-1"}));
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace dropscope

namespace dropscope {
namespace {

const std::string kDetectorScene = kDataDir + "/scenes/detectors.json";

class SnapshotDetectors : public ::testing::Test {
protected:
    std::string out = perTestOutput("dropscope-snapshot-detectors");
    void TearDown() override { fs::remove(out); }
    snapshot::Image shot(std::vector<std::string> extra) {
        std::vector<std::string> arguments{"snapshot", kDetectorScene, "--out",      out,     "--width",
                                           "80",       "--height",     "60",         "--eye", "0,0,12",
                                           "--target", "0,0,5",        "--detectors"};
        arguments.insert(arguments.end(), extra.begin(), extra.end());
        const CliRun run = runDropscope(arguments);
        EXPECT_EQ(run.status, kExitSuccess) << run.err;
        return snapshot::readPng(out);
    }
};

// Seen from behind the screen (it fills the view): without photons its outline only, with them its image.
TEST_F(SnapshotDetectors, DrawsThePlanesWithTheirImagesWhenPhotonsAreTraced) {
    const snapshot::Image outline = shot({});
    const snapshot::Image image = shot({"--photons", "3000"});
    const std::uint8_t* before = outline.pixel(8, 8);
    const std::uint8_t* after = image.pixel(8, 8);
    EXPECT_FALSE(std::equal(before, before + 3, after)) << "the image covers what was background";
    EXPECT_TRUE(std::equal(image.rgba.begin(), image.rgba.end(), shot({"--photons", "3000"}).rgba.begin()))
        << "the same image for the same arguments";
}

TEST_F(SnapshotDetectors, ASceneWithoutDetectorsIsBadInputNamingTheKey) {
    const CliRun run = runDropscope({"snapshot", kOneSphere, "--out", out, "--detectors"});
    expectOneLineFailure(run);
    EXPECT_NE(run.err.find("detectors: --detectors: the scene has no detectors to draw"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace dropscope
