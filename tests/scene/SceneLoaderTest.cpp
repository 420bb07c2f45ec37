#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <sstream>

namespace dropscope {
namespace {

using test::sceneWithShapes;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kSourceDir = DROPSCOPE_SOURCE_DIR;

TEST(SceneLoader, LoadsTheFormatExampleWithGlassDefined) {
    const Scene scene = loadScene(kDataDir + "/scenes/format_example.json");
    EXPECT_EQ(scene.formatVersion, 1);
    EXPECT_EQ(scene.unit, "mm");
    EXPECT_EQ(scene.unitInMetres, 1e-3);
    EXPECT_EQ(scene.wavelengthNm, 532.0);

    // Media keep the file's order; ids are positions.
    ASSERT_EQ(scene.media.size(), 4u);
    EXPECT_EQ(scene.media[0].name, "air");
    EXPECT_EQ(scene.media[1].name, "water");
    EXPECT_EQ(scene.media[2].name, "ink");
    EXPECT_EQ(scene.media[3].name, "glass");
    EXPECT_EQ(scene.ambient, 0u);
    EXPECT_EQ(scene.media[1].n, 1.333);
    EXPECT_EQ(scene.media[1].kappa, 1e-9);
    EXPECT_FALSE(scene.media[1].sigma);
    EXPECT_EQ(scene.media[2].sigma, 0.5);
    EXPECT_EQ(scene.media[2].absorptionPerUnit, 0.5);
    EXPECT_EQ(scene.media[3].absorptionPerUnit, 0.0);

    ASSERT_EQ(scene.shapes.size(), 4u);
    ASSERT_EQ(scene.shapeNames.size(), 4u);
    EXPECT_EQ(scene.shapes[0]->kind(), ShapeKind::Sphere);
    EXPECT_EQ(scene.shapes[1]->kind(), ShapeKind::Ellipsoid);
    EXPECT_EQ(scene.shapes[2]->kind(), ShapeKind::Ellipsoid);
    EXPECT_EQ(scene.shapes[3]->kind(), ShapeKind::Box);
    EXPECT_EQ(scene.shapeNames[0], "d1");
    EXPECT_EQ(scene.shapeNames[1], "");
    EXPECT_EQ(scene.shapes[0]->mediumId(), 1u);
    EXPECT_EQ(scene.mediumOf(*scene.shapes[3]).name, "glass");

    const auto& sphere = static_cast<const Sphere&>(*scene.shapes[0]);
    EXPECT_EQ(sphere.radius(), 1.0);
    const auto& matrixEllipsoid = static_cast<const Ellipsoid&>(*scene.shapes[2]);
    EXPECT_TRUE(matrixEllipsoid.matrix().isApprox(Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix()));
    const auto& box = static_cast<const Box&>(*scene.shapes[3]);
    EXPECT_EQ(box.lower(), Point(-5, -5, -5));
    EXPECT_EQ(box.upper(), Point(5, 5, -4));

    ASSERT_EQ(scene.sources.size(), 1u);
    EXPECT_EQ(scene.sources[0].type, SourceType::Beam);
    EXPECT_EQ(scene.sources[0].origin, Point(0, 0, -10));
    EXPECT_EQ(scene.sources[0].direction.vector(), Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(scene.sources[0].radius, 1.0);
    EXPECT_EQ(scene.origin, kDataDir + "/scenes/format_example.json");
}

TEST(SceneLoader, RotatedEllipsoidHasItsSemiAxesAlongTheRotatedAxes) {
    const Scene scene = parseScene(sceneWithShapes(R"({"type": "ellipsoid", "center": [0, 0, 0],
        "semi_axes": [3, 2, 1], "rotation": {"axis": [0, 0, 2], "angle_deg": 90}, "medium": "water"})"),
                                   "scene.json");
    // 90 degrees about z turns the x semi-axis (3) onto y.
    const Shape& ellipsoid = *scene.shapes[0];
    EXPECT_NEAR(ellipsoid.xMax(), 2.0, 1e-12);
    EXPECT_NEAR(ellipsoid.yMax(), 3.0, 1e-12);
    EXPECT_NEAR(ellipsoid.zMax(), 1.0, 1e-12);
    EXPECT_NEAR(ellipsoid.volume(), 4.0 / 3.0 * std::numbers::pi * 6.0, 1e-12);
}

TEST(SceneLoader, LoadsTheBundledDefaultScene) {
    const Scene scene = loadScene(kSourceDir + "/assets/scenes/default.json");
    EXPECT_GE(scene.shapes.size(), 3u);
    EXPECT_EQ(scene.media.at(scene.ambient).name, "air");
    EXPECT_FALSE(scene.sources.empty());
}

// The first ```json block of docs/scene-format.md is the full example; it must load.
TEST(SceneLoader, LoadsTheFullExampleOfTheFormatDocument) {
    std::ifstream in(kSourceDir + "/docs/scene-format.md");
    ASSERT_TRUE(in) << "docs/scene-format.md is missing";
    std::stringstream text;
    text << in.rdbuf();
    const std::string document = text.str();
    const auto begin = document.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const auto end = document.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);
    const Scene scene = parseScene(document.substr(begin + 8, end - begin - 8), "docs/scene-format.md");
    EXPECT_FALSE(scene.shapes.empty());
}

TEST(SceneLoader, DefaultsWhenOptionalKeysAreLeftOut) {
    const Scene scene = parseScene(R"({"dropscope": 1})", "scene.json");
    EXPECT_EQ(scene.unit, "mm");
    EXPECT_EQ(scene.unitInMetres, 1e-3);
    EXPECT_EQ(scene.wavelengthNm, 532.0);
    EXPECT_TRUE(scene.shapes.empty());
    EXPECT_TRUE(scene.sources.empty());
    // Without "ambient", a built-in vacuum (n = 1) is added and is the ambient medium.
    ASSERT_EQ(scene.media.size(), 1u);
    EXPECT_EQ(scene.media[0].name, "vacuum");
    EXPECT_EQ(scene.media[0].n, 1.0);
    EXPECT_EQ(scene.ambient, 0u);
}

TEST(SceneLoader, BuiltInVacuumComesAfterTheFileMediaAndShapesMayUseIt) {
    const Scene scene = parseScene(R"({"dropscope": 1, "media": {"water": {"n": 1.333}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "vacuum"}]})",
                                   "scene.json");
    ASSERT_EQ(scene.media.size(), 2u);
    EXPECT_EQ(scene.media[1].name, "vacuum");
    EXPECT_EQ(scene.ambient, 1u);
    EXPECT_EQ(scene.shapes[0]->mediumId(), 1u);
}

TEST(SceneLoader, AFileMediumNamedVacuumIsTheDefaultAmbient) {
    const Scene scene = parseScene(R"({"dropscope": 1, "media": {"vacuum": {"n": 1.0003}}})", "scene.json");
    ASSERT_EQ(scene.media.size(), 1u);
    EXPECT_EQ(scene.ambient, 0u);
    EXPECT_EQ(scene.media[0].n, 1.0003);
}

TEST(SceneLoader, UnitsConvertToMetres) {
    const std::pair<const char*, double> units[] = {{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}};
    for (const auto& [unit, metres] : units) {
        const Scene scene = parseScene(std::string(R"({"dropscope": 1, "unit": ")") + unit + R"("})", "scene.json");
        EXPECT_EQ(scene.unitInMetres, metres) << unit;
    }
}

TEST(SceneLoader, KappaBecomesAbsorptionPerSceneUnit) {
    // sigma = 4 pi kappa / lambda with lambda = 500 nm = 0.5 um in a micrometre scene.
    const Scene scene = parseScene(
        R"({"dropscope": 1, "unit": "um", "wavelength_nm": 500, "media": {"dye": {"n": 1.4, "kappa": 0.001}}})",
        "scene.json");
    EXPECT_DOUBLE_EQ(scene.wavelengthInSceneUnits(), 0.5);
    EXPECT_DOUBLE_EQ(scene.media[0].absorptionPerUnit, 4.0 * std::numbers::pi * 0.001 / 0.5);
    EXPECT_DOUBLE_EQ(absorptionFromExtinction(1e-9, 532e-6), 4.0 * std::numbers::pi * 1e-9 / 532e-6);
}

TEST(SceneLoader, ShapeIdsAreTheFileOrder) {
    const Scene scene = parseScene(sceneWithShapes(R"(
        {"type": "box", "min": [10, 0, 0], "max": [11, 1, 1], "medium": "water", "name": "c"},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water", "name": "a"},
        {"type": "sphere", "center": [5, 0, 0], "radius": 1, "medium": "water"},
        {"type": "sphere", "center": [-5, 0, 0], "radius": 1, "medium": "water", "name": "b"})"),
                                   "scene.json");
    ASSERT_EQ(scene.shapes.size(), 4u);
    EXPECT_EQ(scene.shapeNames, (std::vector<std::string>{"c", "a", "", "b"}));
    EXPECT_EQ(scene.shapes[0]->kind(), ShapeKind::Box);
    EXPECT_EQ(scene.shapes[3]->xMin(), -6.0);
}

TEST(SceneLoader, ReadsEverySourceType) {
    const Scene scene = parseScene(R"({"dropscope": 1, "sources": [
        {"type": "beam", "origin": [0, 0, -1], "direction": [0, 0, 5], "radius": 0.5},
        {"type": "ray", "origin": [1, 2, 3], "direction": [3, 0, 4]},
        {"type": "point", "origin": [7, 8, 9]}]})",
                                   "scene.json");
    ASSERT_EQ(scene.sources.size(), 3u);
    EXPECT_EQ(scene.sources[0].type, SourceType::Beam);
    EXPECT_EQ(scene.sources[0].direction.vector(), Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(scene.sources[1].type, SourceType::Ray);
    EXPECT_TRUE(scene.sources[1].direction.vector().isApprox(Eigen::Vector3d(0.6, 0, 0.8)));
    EXPECT_EQ(scene.sources[2].type, SourceType::PointSource);
    EXPECT_EQ(scene.sources[2].origin, Point(7, 8, 9));
    EXPECT_EQ(sourceTypeName(scene.sources[2].type), "point");
}

TEST(SceneLoader, FindMediumByName) {
    const Scene scene = loadScene(kDataDir + "/scenes/format_example.json");
    EXPECT_EQ(scene.findMedium("ink"), MediumId{2});
    EXPECT_FALSE(scene.findMedium("glas"));
}

}  // namespace
}  // namespace dropscope
