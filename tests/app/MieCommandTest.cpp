// `dropscope mie`, run in-process: its two files against Bohren & Huffman's sphere, the scene's sphere and droplet
// cloud against the same numbers given directly, and bad input (exit 2, one line, nothing written).
#include "app/CliRun.hpp"
#include "cli/Cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

class MieCommand : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::freshTestDirectory("mie"); }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    CliRun mie(std::vector<std::string> arguments, const std::string& out = "out") const {
        arguments.insert(arguments.begin(), "mie");
        arguments.insert(arguments.end(), {"--out", path(out)});
        return runDropscope(arguments);
    }
    Json summary(const std::string& out = "out") const {
        std::ifstream in(path(out + "/summary.json"));
        return Json::parse(in);
    }
    std::vector<std::vector<double>> rows(const std::string& out = "out") const {
        std::ifstream in(path(out + "/mie.csv"));
        std::string line;
        std::getline(in, line);
        header_ = line;
        std::vector<std::vector<double>> table;
        while (std::getline(in, line)) {
            std::vector<double> row;
            std::istringstream fields(line);
            std::string cell;
            while (std::getline(fields, cell, ',')) row.push_back(std::stod(cell));
            table.push_back(row);
        }
        return table;
    }
    // A scene with a water sphere of radius 0.0005 mm and a cloud of water droplets of radius 0.0004 mm, in
    // an ambient of index `ambient`, at 500 nm.
    void writeScene(double ambient) const {
        std::ofstream(path("scene.json")) << R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 500, "ambient": "host",
          "media": {"host": {"n": )" + std::to_string(ambient) +
                                                 R"(}, "water": {"n": 1.3337, "kappa": 1e-4}},
          "shapes": [{"type": "box", "min": [1, 1, 1], "max": [2, 2, 2], "medium": "water"},
                     {"type": "sphere", "center": [0, 0, 0], "radius": 0.0005, "medium": "water"}],
          "generators": [{"type": "droplet_cloud", "region": {"min": [-1, -1, 0.5], "max": [1, 1, 0.8]}, "count": 5,
                          "radius": {"distribution": "fixed", "value": 0.0004}, "medium": "water", "seed": 1}],
          "sources": []})";
    }

    fs::path dir_;
    mutable std::string header_;
};

TEST_F(MieCommand, BohrenAndHuffmansSphereWithBinsAddingUpToQsca) {
    // Bohren & Huffman, Appendix A: m = 1.55, x = 5.21282 (a = 0.525 um, lambda = 0.6328 um), Q_sca = 3.10543,
    // Q_back = 2.92534.
    const CliRun run = mie({"--index", "1.55", "--x", "5.21282", "--bins", "36"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    EXPECT_TRUE(run.err.empty()) << run.err;
    const Json s = summary();
    EXPECT_NEAR(s["qsca"].get<double>(), 3.10543, 1e-5);
    EXPECT_NEAR(s["qext"].get<double>(), 3.10543, 1e-5);
    EXPECT_NEAR(s["qback"].get<double>(), 2.92534, 1e-5);
    EXPECT_EQ(s["qabs"].get<double>(), 0.0);
    EXPECT_EQ(s["x"].get<double>(), 5.21282);
    EXPECT_EQ(s["index"].get<double>(), 1.55);
    EXPECT_EQ(s["kappa"].get<double>(), 0.0);
    EXPECT_EQ(s["sizes"], 1);
    const auto table = rows();
    EXPECT_EQ(header_, "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr,p12_over_p11,p33_over_p11,p34_over_p11");
    ASSERT_EQ(table.size(), 36u);
    double total = 0.0;
    for (const auto& row : table) {
        ASSERT_EQ(row.size(), 7u);
        total += row[2];
        const double solidAngle =
            2.0 * std::numbers::pi *
            (std::cos(row[0] * std::numbers::pi / 180) - std::cos(row[1] * std::numbers::pi / 180));
        EXPECT_NEAR(row[3] * solidAngle, row[2], 1e-12 * row[2]);
        EXPECT_LE(std::abs(row[4]), 1.0);
    }
    EXPECT_NEAR(total, s["qsca"].get<double>(), 1e-10);
    EXPECT_EQ(table.front()[0], 0.0);
    EXPECT_EQ(table.back()[1], 180.0);
}

TEST_F(MieCommand, AScenesSphereAndCloudAreTheirSizeParametersAndRelativeIndex) {
    writeScene(1.2);
    // x = 2 pi a n_ambient / lambda; m = (1.3337 + 1e-4 i) / 1.2.
    const double wavelength = 500e-6;
    const double xSphere = 2.0 * std::numbers::pi * 0.0005 * 1.2 / wavelength;
    const double xCloud = 2.0 * std::numbers::pi * 0.0004 * 1.2 / wavelength;
    const auto exact = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", value);
        return std::string(text);
    };
    const auto direct = [&](double x, const std::string& out) {
        return mie({"--index", exact(1.3337 / 1.2), "--kappa", exact(1e-4 / 1.2), "--x", exact(x), "--bins", "20"},
                   out);
    };
    ASSERT_EQ(mie({"--scene", path("scene.json"), "--shape", "1", "--bins", "20"}, "sphere").status, kExitSuccess);
    ASSERT_EQ(mie({"--scene", path("scene.json"), "--generator", "0", "--bins", "20"}, "cloud").status, kExitSuccess);
    ASSERT_EQ(direct(xSphere, "sphere-direct").status, kExitSuccess);
    ASSERT_EQ(direct(xCloud, "cloud-direct").status, kExitSuccess);
    for (const auto& [scene, given] : {std::pair{"sphere", "sphere-direct"}, std::pair{"cloud", "cloud-direct"}}) {
        const Json a = summary(scene);
        const Json b = summary(given);
        // The same numbers but for the last bits of x = k a and m = n / n_ambient computed two ways.
        for (const char* key : {"qext", "qsca", "qabs", "g", "x", "index", "kappa"}) {
            EXPECT_NEAR(a[key].get<double>(), b[key].get<double>(), 1e-12 * std::abs(b[key].get<double>()))
                << scene << " " << key;
        }
        EXPECT_GT(a["qabs"].get<double>(), 0.0) << "kappa from the medium";
    }
    const Json sphere = summary("sphere");
    EXPECT_EQ(sphere["shape"], 1);
    EXPECT_EQ(sphere["medium"], "water");
    EXPECT_EQ(sphere["ambient_index"].get<double>(), 1.2);
    EXPECT_EQ(summary("cloud")["generator"], 0);
}

TEST_F(MieCommand, ARangeAveragesItsSizes) {
    ASSERT_EQ(mie({"--index", "1.33", "--x-range", "10", "20", "--x-count", "5", "--bins", "10"}).status, kExitSuccess);
    const Json s = summary();
    EXPECT_EQ(s["sizes"], 5);
    EXPECT_EQ(s["x_lo"].get<double>(), 10.0);
    EXPECT_EQ(s["x_hi"].get<double>(), 20.0);
    EXPECT_GT(s["x"].get<double>(), 15.0) << "the mean weighted by cross-section leans to the large";
    ASSERT_EQ(mie({"--index", "1.33", "--x-range", "10", "20", "--bins", "10"}, "default").status, kExitSuccess);
    EXPECT_EQ(summary("default")["sizes"], 100) << "one size per 0.1 of x by default";
}

TEST_F(MieCommand, BadInputIsOneLineAndWritesNothing) {
    writeScene(1.0);
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--index", "1.33", "--x", "0"}, "--x"},
        {{"--index", "1.33", "--x", "-2"}, "--x"},
        {{"--index", "1.33", "--x", "3e4"}, "--x"},
        {{"--index", "0", "--x", "10"}, "--index"},
        {{"--index", "-1.3", "--x", "10"}, "--index"},
        {{"--index", "1.33", "--kappa", "-0.1", "--x", "10"}, "--kappa"},
        {{"--index", "1.33"}, "exactly one of"},
        {{"--index", "1.33", "--x", "10", "--x-range", "1", "2"}, "exactly one of"},
        {{"--index", "1.33", "--x-range", "20", "10"}, "--x-range"},
        {{"--index", "1.33", "--x", "10", "--x-count", "4"}, "--x-count"},
        {{"--x", "10"}, "--index"},
        {{"--scene", path("scene.json"), "--shape", "0"}, "is a box"},
        {{"--scene", path("scene.json"), "--shape", "9"}, "--shape 9"},
        {{"--scene", path("scene.json"), "--generator", "1"}, "--generator 1"},
        {{"--scene", path("scene.json")}, "choose one with --shape ID or --generator I"},
        {{"--scene", path("scene.json"), "--index", "1.3", "--shape", "1"}, "--index"},
        {{"--scene", path("missing.json")}, "missing.json"},
    };
    for (const auto& [arguments, expected] : cases) {
        const CliRun run = mie(arguments, "bad");
        SCOPED_TRACE(expected);
        expectOneLineFailure(run);
        EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
        EXPECT_FALSE(fs::exists(path("bad/summary.json")));
        EXPECT_FALSE(fs::exists(path("bad/mie.csv")));
    }
}

}  // namespace
}  // namespace dropscope
