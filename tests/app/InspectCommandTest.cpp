#include "app/CliRun.hpp"
#include "cli/Cli.hpp"
#include "tree/OctreeTypes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using test::CliRun;
using test::expectOneLineFailure;
using test::runDropscope;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kSourceDir = DROPSCOPE_SOURCE_DIR;
const std::string kOneSphere = kDataDir + "/scenes/one_sphere.json";  // r = 2 um at (1, 2, 3)

TEST(InspectCommand, TableShowsTheSphereVolumeAndArea) {
    const CliRun run = runDropscope({"inspect", kOneSphere});
    EXPECT_EQ(run.status, kExitSuccess);
    EXPECT_EQ(run.err, "");
    // 4/3 pi 2^3 = 33.5103 and 4 pi 2^2 = 50.2655 to 6 digits.
    EXPECT_NE(run.out.find("33.5103"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("50.2655"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("-1 .. 3"), std::string::npos) << run.out;  // x range of the sphere
    EXPECT_NE(run.out.find("volume [um^3]"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("drop"), std::string::npos);
    EXPECT_NE(run.out.find("water"), std::string::npos);
    EXPECT_NE(run.out.find("shapes        1 (1 sphere)"), std::string::npos) << run.out;
}

TEST(InspectCommand, TableColumnsAreAligned) {
    const CliRun run = runDropscope({"inspect", kSourceDir + "/assets/scenes/default.json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    // In the shapes table the "medium" column starts at the same place on every row.
    std::istringstream lines(run.out.substr(run.out.find("\nshapes\n") + 8));
    std::string heading;
    std::getline(lines, heading);
    const auto column = heading.find("medium");
    for (std::string line; std::getline(lines, line) && !line.empty();) {
        EXPECT_TRUE(line.substr(column).starts_with("water") || line.substr(column).starts_with("glass")) << line;
    }
}

TEST(InspectCommand, ParametricAndImplicitShapesShowTheirPreset) {
    const std::string gallery = kSourceDir + "/assets/scenes/shapes_gallery.json";
    const CliRun table = runDropscope({"inspect", gallery});
    ASSERT_EQ(table.status, kExitSuccess) << table.err;
    for (const char* type :
         {"parametric bezier", "parametric torus", "parametric sphere", "implicit blob", "implicit superellipsoid"}) {
        EXPECT_NE(table.out.find(type), std::string::npos) << type << "\n" << table.out;
    }
    const CliRun run = runDropscope({"inspect", gallery, "--json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const nlohmann::json report = nlohmann::json::parse(run.out);
    const auto& ring = report["shapes"][1];
    EXPECT_EQ(ring["type"], "parametric");
    EXPECT_EQ(ring["preset"], "torus");
    // Torus R = 1, r = 0.3: V = 2 pi^2 R r^2, S = 4 pi^2 R r (a rotation changes neither).
    EXPECT_NEAR(ring["volume"].get<double>(), 2 * std::numbers::pi * std::numbers::pi * 0.09, 1e-9);
    EXPECT_NEAR(ring["surface_area"].get<double>(), 4 * std::numbers::pi * std::numbers::pi * 0.3, 1e-9);
    // Its x extent is the translation +- (R + r): a rotation about x leaves x alone.
    EXPECT_NEAR(ring["bounds"]["min"][0].get<double>(), -3.2 - 1.3, 1e-9);
    EXPECT_NEAR(ring["bounds"]["max"][0].get<double>(), -3.2 + 1.3, 1e-9);
    EXPECT_EQ(report["shapes"][0]["preset"], "bezier");
    EXPECT_EQ(report["totals"]["shapes_by_type"]["parametric"], 3);
    EXPECT_EQ(report["totals"]["shapes_by_type"]["implicit"], 2);
    // The implicit integrals carry error estimates, small against their values.
    const auto& blob = report["shapes"][3];
    ASSERT_EQ(blob["preset"], "blob");
    EXPECT_GT(blob["volume_error"].get<double>(), 0.0);
    EXPECT_LT(blob["volume_error"].get<double>(), 1e-2 * blob["volume"].get<double>());
    EXPECT_LT(blob["surface_area_error"].get<double>(), 1e-2 * blob["surface_area"].get<double>());
    EXPECT_FALSE(ring.contains("volume_error"));
}

TEST(InspectCommand, JsonHasEveryDocumentedKeyAndFullPrecision) {
    const CliRun run = runDropscope({"inspect", kOneSphere, "--json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const nlohmann::json report = nlohmann::json::parse(run.out);
    for (const char* key : {"scene", "format", "unit", "unit_in_metres", "wavelength_nm", "wavelength_in_unit",
                            "ambient", "media", "shapes", "sources", "totals"}) {
        EXPECT_TRUE(report.contains(key)) << key;
    }
    EXPECT_EQ(report["unit"], "um");
    EXPECT_EQ(report["ambient"], "air");
    const auto& shape = report["shapes"][0];
    EXPECT_EQ(shape["id"], 0);
    EXPECT_EQ(shape["type"], "sphere");
    EXPECT_EQ(shape["name"], "drop");
    EXPECT_EQ(shape["medium"], "water");
    EXPECT_EQ(shape["medium_id"], 1);
    EXPECT_EQ(shape["bounds"]["min"], nlohmann::json({-1.0, 0.0, 1.0}));
    EXPECT_EQ(shape["bounds"]["max"], nlohmann::json({3.0, 4.0, 5.0}));
    EXPECT_DOUBLE_EQ(shape["volume"].get<double>(), 4.0 / 3.0 * std::numbers::pi * 8.0);
    EXPECT_DOUBLE_EQ(shape["surface_area"].get<double>(), 4.0 * std::numbers::pi * 4.0);
    const auto& medium = report["media"][1];
    for (const char* key : {"id", "name", "n", "kappa", "sigma", "absorption_per_unit"}) {
        EXPECT_TRUE(medium.contains(key)) << key;
    }
    const auto& source = report["sources"][0];
    EXPECT_EQ(source["type"], "ray");
    EXPECT_EQ(source["direction"], nlohmann::json({0.0, 0.0, 1.0}));
    EXPECT_TRUE(source["radius"].is_null());
    EXPECT_EQ(source["polarisation"], "unpolarised");
    const auto& totals = report["totals"];
    EXPECT_EQ(totals["shapes"], 1);
    EXPECT_EQ(totals["shapes_by_type"],
              nlohmann::json({{"box", 0}, {"ellipsoid", 0}, {"implicit", 0}, {"parametric", 0}, {"sphere", 1}}));
    EXPECT_DOUBLE_EQ(totals["volume"].get<double>(), 4.0 / 3.0 * std::numbers::pi * 8.0);
    EXPECT_EQ(totals["bounds"], shape["bounds"]);
}

TEST(InspectCommand, SourcesShowTheirPolarisationAsTheSceneGivesIt) {
    const std::string scene = kSourceDir + "/assets/scenes/brewster.json";
    const CliRun json = runDropscope({"inspect", "--json", scene});
    ASSERT_EQ(json.status, kExitSuccess) << json.err;
    const nlohmann::json report = nlohmann::json::parse(json.out);
    EXPECT_EQ(report["sources"][1]["polarisation"],
              nlohmann::json({{"linear_deg", 0.0}, {"reference", {0.5547002, 0.0, 0.8320503}}}));
    const CliRun text = runDropscope({"inspect", scene});
    ASSERT_EQ(text.status, kExitSuccess) << text.err;
    EXPECT_NE(text.out.find("linear 0 deg from (0, 1, 0)"), std::string::npos) << text.out;
}

TEST(InspectCommand, JsonTotalsOfTheDefaultScene) {
    const CliRun run = runDropscope({"inspect", "--json", kSourceDir + "/assets/scenes/default.json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const nlohmann::json report = nlohmann::json::parse(run.out);
    double volume = 0.0;
    for (const auto& shape : report["shapes"]) volume += shape["volume"].get<double>();
    EXPECT_EQ(report["totals"]["shapes"], report["shapes"].size());
    EXPECT_DOUBLE_EQ(report["totals"]["volume"].get<double>(), volume);
}

TEST(InspectCommand, ReportsTheOctreePerLevel) {
    const CliRun run = runDropscope({"inspect", kSourceDir + "/assets/scenes/default.json", "--json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const nlohmann::json octree = nlohmann::json::parse(run.out)["octree"];
    EXPECT_EQ(octree["max_depth"], 10);
    EXPECT_EQ(octree["max_shapes_per_leaf"], OctreeSettings{}.maxShapesPerLeaf);
    ASSERT_FALSE(octree["levels"].empty());
    EXPECT_EQ(octree["levels"][0]["cells"], 1);
    std::size_t stored = 0;
    for (const auto& level : octree["levels"]) stored += level["shapes_stored"].get<std::size_t>();
    EXPECT_GE(stored, 5u);  // every shape of the scene, some perhaps in several cells
    EXPECT_GT(octree["bytes"].get<std::size_t>(), 0u);
    const CliRun table = runDropscope({"inspect", kSourceDir + "/assets/scenes/default.json"});
    EXPECT_NE(table.out.find("octree (max_depth 10, max_shapes_per_leaf " +
                             std::to_string(OctreeSettings{}.maxShapesPerLeaf) + ")"),
              std::string::npos)
        << table.out;
    EXPECT_NE(table.out.find("leaves by shape count"), std::string::npos);
}

TEST(InspectCommand, MissingFileExitsTwoWithOneLine) {
    const std::string missing = kDataDir + "/scenes/does_not_exist.json";
    const CliRun run = runDropscope({"inspect", missing});
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, missing + ": no such file\n");
    EXPECT_EQ(run.out, "");
}

TEST(InspectCommand, BadSceneExitsTwoWithTheSceneError) {
    const std::string file = kDataDir + "/scenes/overlapping.json";
    const CliRun run = runDropscope({"inspect", file, "--json"});
    expectOneLineFailure(run);
    EXPECT_EQ(run.err, file + R"(: shapes[1]: sphere "d2" overlaps shapes[0] (sphere "d1"); shapes may touch or )"
                              "nest (anything in a box, a sphere in a sphere), not partly overlap\n");
    EXPECT_EQ(run.out, "");
}

TEST(InspectCommand, MalformedSceneExitsTwo) {
    const CliRun run = runDropscope({"inspect", kDataDir + "/scenes/malformed.json"});
    expectOneLineFailure(run);
    EXPECT_NE(run.err.find("line 4, column 10"), std::string::npos) << run.err;
}

TEST(InspectCommand, DispersiveMediaAndSpectraAreShown) {
    const std::string scene = kSourceDir + "/assets/scenes/sunlit-rainbow.json";
    const CliRun table = runDropscope({"inspect", scene});
    ASSERT_EQ(table.status, kExitSuccess) << table.err;
    EXPECT_NE(table.out.find("media (at 550 nm)"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("n: builtin water (20 C), kappa: builtin water"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("dispersive media"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("sun 380-780 nm, divergence 0.266 deg"), std::string::npos) << table.out;

    const CliRun run = runDropscope({"inspect", scene, "--json"});
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    const nlohmann::json* water = nullptr;
    for (const auto& medium : json["media"]) {
        if (medium["name"] == "water") water = &medium;
        if (medium["name"] == "air") {
            EXPECT_TRUE(medium["dispersion"].is_null());
        }
    }
    ASSERT_NE(water, nullptr);
    const nlohmann::json& values = (*water)["dispersion"]["values"];
    // no source has lines: 400, 550 and 700 nm, the index falling with the wavelength
    ASSERT_EQ(values.size(), 3u);
    EXPECT_EQ(values[0]["wavelength_nm"], 400.0);
    EXPECT_EQ(values[2]["wavelength_nm"], 700.0);
    EXPECT_GT(values[0]["n"].get<double>(), values[1]["n"].get<double>());
    EXPECT_GT(values[1]["n"].get<double>(), values[2]["n"].get<double>());
    EXPECT_EQ(values[1]["n"], (*water)["n"]);  // 550 nm is the scene wavelength
    const nlohmann::json& source = json["sources"][0];
    EXPECT_EQ(source["spectrum"]["kind"], "sun");
    EXPECT_EQ(source["spectrum"]["kelvin"], 5778.0);
    EXPECT_EQ(source["divergence_deg"], 0.266);
}

}  // namespace
}  // namespace dropscope
