// dropscope snapshot's layer switches (docs/rendering.md): every one renders, and every bad value or
// combination is bad input, exit 2 with one line.
#include "CliRun.hpp"
#include "snapshot/Image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace dropscope {
namespace {

namespace fs = std::filesystem;
using test::expectOneLineFailure;
using test::runDropscope;

const std::string kDefaultScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";
const std::string kNoSources = std::string(DROPSCOPE_TEST_DATA_DIR) + "/scenes/no_sources.json";

std::string outputPng(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / "dropscope-snapshot-layers";
    fs::create_directories(folder);
    // CTest runs the tests of this file in parallel: each test writes under its own name.
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    return (folder / (test + "-" + name + ".png")).string();
}

test::CliRun snapshot(const std::string& scene, const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> arguments{"snapshot", scene, "--out", out, "--width", "160", "--height", "120"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return runDropscope(arguments);
}

TEST(SnapshotLayerOptions, EverySwitchRenders) {
    const std::vector<std::vector<std::string>> cases{
        {"--ray-tree"},
        {"--ray-tree", "--markers", "--translucent"},
        {"--octree-level", "1", "--octree-filter", "upto", "--octree-colour", "occupancy"},
        {"--octree-filter", "leaves"},
        {"--traversal", "--no-shapes"},
        {"--paths", "5", "--colour-by", "event", "--markers"},
        {"--paths", "5", "--colour-by", "dolp", "--polarisation", "stokes"},
        {"--paths", "5", "--colour-by", "wavelength"},
        {"--paths", "5", "--ray-tree", "--polarisation", "none"},
        {"--sources", "--axes", "--grid", "--select", "4"},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const std::string out = outputPng("switch-" + std::to_string(k));
        fs::remove(out);
        const test::CliRun run = snapshot(kDefaultScene, out, cases[k]);
        EXPECT_EQ(run.status, kExitSuccess) << "case " << k << ": " << run.err;
        EXPECT_TRUE(run.err.empty()) << "case " << k << ": " << run.err;
        EXPECT_GT(fs::file_size(out), 0u) << "case " << k;
    }
}

// Each switch adds pixels of its layer's colour (docs/rendering.md) to the plain picture.
TEST(SnapshotLayerOptions, EachLayerAddsItsColour) {
    using Rgb = std::function<bool(int r, int g, int b)>;
    struct Case {
        std::vector<std::string> arguments;
        Rgb colour;
        int atLeast;
    };
    const std::vector<Case> cases{
        {{"--select", "1"}, [](int r, int g, int b) { return r > 150 && g > 120 && b < 80; }, 20},  // highlight
        {{"--traversal"}, [](int r, int g, int b) { return r < 60 && g > 200 && b > 170; }, 20},    // cyan
        {{"--ray-tree"}, [](int r, int g, int b) { return r > 200 && g > 190 && b < 80; }, 10},     // weight 1
        {{"--sources"}, [](int r, int g, int b) { return r > 230 && g > 220 && b > 100 && b < 180; }, 10},
        {{"--axes"}, [](int r, int g, int b) { return r > 200 && g < 100 && b < 100; }, 3},  // x red
        {{"--grid"},                                                                         // grey
         [](int r, int g, int b) { return r > 70 && r < 95 && g > 75 && g < 100 && b > 85 && b < 110; },
         20},
        {{"--paths", "10", "--colour-by", "event"},  // emissions white
         [](int r, int g, int b) { return r > 240 && g > 240 && b > 240; },
         5},
        {{"--paths", "10", "--colour-by", "dolp"},  // the unpolarised beam: viridis(0), dark purple
         [](int r, int g, int b) { return r > 50 && r < 90 && g < 25 && b > 65 && b < 105; },
         5},
        {{"--paths", "10", "--colour-by", "wavelength"},  // the scene's 532 nm: green (displayColourOfWavelength)
         [](int r, int g, int) { return r < 60 && g > 230; },
         5},
    };
    const std::string plainPng = outputPng("plain");
    ASSERT_EQ(snapshot(kDefaultScene, plainPng, {}).status, kExitSuccess);
    const snapshot::Image plain = snapshot::readPng(plainPng);
    for (const Case& layer : cases) {
        const std::string out = outputPng("layer");
        ASSERT_EQ(snapshot(kDefaultScene, out, layer.arguments).status, kExitSuccess) << layer.arguments[0];
        const snapshot::Image image = snapshot::readPng(out);
        int added = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                const std::uint8_t* q = plain.pixel(x, y);
                if ((p[0] != q[0] || p[1] != q[1] || p[2] != q[2]) && layer.colour(p[0], p[1], p[2])) ++added;
            }
        }
        EXPECT_GE(added, layer.atLeast) << layer.arguments[0];
    }
}

TEST(SnapshotLayerOptions, BadValuesAreBadInput) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--octree-filter", "all"}, "--octree-filter: all not in {level,upto,leaves}"},
        {{"--octree-colour", "heat", "--octree-level", "1"}, "--octree-colour: heat not in {level,occupancy}"},
        {{"--colour-by", "type"}, "--colour-by: type not in {weight,event,dolp,wavelength}"},
        {{"--polarisation", "linear"}, "--polarisation: linear not in {stokes,none}"},
        {{"--colour-by", "dolp", "--polarisation", "none"}, "--colour-by dolp: needs --polarisation stokes"},
        {{"--select", "-1"}, "--select: Value -1 not in range"},
        {{"--select", "one"}, "--select: Value one not in range"},
        {{"--octree-filter", "upto"}, "--octree-filter upto: needs --octree-level L"},
        {{"--octree-filter", "leaves", "--octree-level", "2"}, "--octree-filter leaves: takes no --octree-level"},
        {{"--octree-colour", "occupancy"},
         "--octree-colour occupancy: needs --octree-level L or --octree-filter leaves"},
    };
    for (const auto& [arguments, message] : cases) {
        const std::string out = outputPng("bad");
        fs::remove(out);
        const test::CliRun run = snapshot(kDefaultScene, out, arguments);
        expectOneLineFailure(run);
        EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST(SnapshotLayerOptions, SelectingAShapeThatDoesNotExistNamesTheScene) {
    const test::CliRun run = snapshot(kDefaultScene, outputPng("bad"), {"--select", "5"});
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, kDefaultScene + ": shapes: --select 5: no such shape (the scene has 5, ids from 0)\n");
}

TEST(SnapshotLayerOptions, RayTreeAndTraversalNeedASource) {
    for (const std::string option : {"--ray-tree", "--traversal"}) {
        const test::CliRun run = snapshot(kNoSources, outputPng("bad"), {option});
        expectOneLineFailure(run);
        EXPECT_EQ(run.err, kNoSources + ": sources: " + option + " needs a light source, and the scene has none\n");
    }
}

}  // namespace
}  // namespace dropscope
