// Every scene-file error: one line "FILE: JSON.PATH: message", raised where the bad value is read.
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using test::sceneErrorOf;
using test::sceneWithShapes;

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;

std::string shapeError(const std::string& shape) { return sceneErrorOf(sceneWithShapes(shape)); }

std::string sourceError(const std::string& source) {
    return sceneErrorOf(R"({"dropscope": 1, "sources": [)" + source + "]}");
}

std::string loadError(const std::string& file) {
    try {
        loadScene(file);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

// The scene format's example with one mistake: it uses "glass" without defining it.
TEST(SceneError, FormatExampleNamesTheUndefinedGlass) {
    const char* formatExample = R"({ "dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
  "media":  { "air": {"n": 1.0}, "water": {"n": 1.333, "kappa": 1e-9}, "ink": {"n": 1.0, "sigma": 0.5} },
  "shapes": [ {"type": "sphere", "center": [0,0,0], "radius": 1, "medium": "water", "name": "d1"},
              {"type": "ellipsoid", "center": [3,0,0], "semi_axes": [1.5,1,0.5],
               "rotation": {"axis": [0,0,1], "angle_deg": 30}, "medium": "water"},
              {"type": "ellipsoid", "center": [0,3,0], "matrix": [[1,0,0],[0,2,0],[0,0,3]], "medium": "water"},
              {"type": "box", "min": [-5,-5,-5], "max": [5,5,-4], "medium": "glass"} ],
  "sources": [ {"type": "beam", "origin": [0,0,-10], "direction": [0,0,1], "radius": 1} ] })";
    EXPECT_EQ(sceneErrorOf(formatExample),
              R"(scene.json: shapes[3].medium: unknown medium "glass" (defined: air, water, ink))");
}

TEST(SceneError, CarriesPathAndDetailSeparately) {
    try {
        parseScene(sceneWithShapes(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0, "medium": "water"})"),
                   "scene.json");
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.jsonPath(), "shapes[0].radius");
        EXPECT_EQ(error.detail(), "must be > 0");
    }
}

TEST(SceneError, MissingFile) {
    const std::string file = kDataDir + "/scenes/does_not_exist.json";
    EXPECT_EQ(loadError(file), file + ": no such file");
}

TEST(SceneError, DirectoryInsteadOfFile) {
    EXPECT_EQ(loadError(kDataDir), kDataDir + ": is a directory, not a scene file");
}

TEST(SceneError, MalformedJsonGivesLineAndColumn) {
    const std::string file = kDataDir + "/scenes/malformed.json";
    EXPECT_EQ(loadError(file),
              file +
                  ": line 4, column 10: syntax error while parsing object - unexpected string literal; "
                  "expected '}'");
    EXPECT_EQ(sceneErrorOf(""),
              "scene.json: line 1, column 1: syntax error while parsing value - unexpected end "
              "of input; expected '[', '{', or a literal");
    EXPECT_EQ(sceneErrorOf("{\"dropscope\": 1} x"),
              "scene.json: line 1, column 18: syntax error while parsing value - invalid literal; last read: "
              "'1} x'; expected end of input");
}

TEST(SceneError, NumberBeyondDoubleRangeIsRejectedByTheParser) {
    EXPECT_EQ(sceneErrorOf("{\"dropscope\": 1,\n \"wavelength_nm\": 1e999}"),
              "scene.json: line 2, column 23: number overflow parsing '1e999'");
}

TEST(SceneError, DuplicateKey) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"water": {"n": 1.3, "n": 1.4}}})"),
              R"(scene.json: media.water: duplicate key "n")");
}

TEST(SceneError, NestingIsLimited) {
    const std::string deep = R"({"dropscope": 1, "shapes": )" + std::string(100000, '[');
    const std::string message = sceneErrorOf(deep);
    EXPECT_TRUE(message.starts_with("scene.json: shapes[0][0][0]")) << message;
    EXPECT_TRUE(message.ends_with(": nested more than 64 levels deep")) << message;
}

TEST(SceneError, RootMustBeAnObject) { EXPECT_EQ(sceneErrorOf("[1, 2]"), "scene.json: expected an object, got array"); }

TEST(SceneError, FormatVersion) {
    EXPECT_EQ(sceneErrorOf(R"({"unit": "mm"})"), R"(scene.json: missing required key "dropscope")");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 2})"),
              "scene.json: dropscope: unsupported format version 2 (this program reads version 1)");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": "1"})"), "scene.json: dropscope: expected an integer, got string");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1.5})"), "scene.json: dropscope: must be an integer, got 1.5");
}

TEST(SceneError, UnknownKeySuggestsTheNearestValidKey) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radus": 1, "medium": "water"})"),
              R"(scene.json: shapes[0]: unknown key "radus" (did you mean "radius"?))");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "wavelength": 500})"),
              R"(scene.json: unknown key "wavelength" (did you mean "wavelength_nm"?))");
}

TEST(SceneError, UnknownKeyWithoutANearOneListsTheValidKeys) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "camera": {}})"),
              R"(scene.json: unknown key "camera" (valid keys: dropscope, unit, wavelength_nm, ambient, media, )"
              R"(shapes, sources, octree, generators, view, detectors))");
    EXPECT_EQ(sourceError(R"({"type": "point", "origin": [0, 0, 0], "direction": [0, 0, 1]})"),
              R"(scene.json: sources[0]: unknown key "direction" (valid keys: type, origin, polarisation, spectrum))");
}

TEST(SceneError, UnknownTypes) {
    EXPECT_EQ(
        shapeError(R"({"type": "cube", "medium": "water"})"),
        R"(scene.json: shapes[0].type: unknown shape type "cube" (known: sphere, ellipsoid, box, parametric, implicit))");
    EXPECT_EQ(sourceError(R"({"type": "laser", "origin": [0, 0, 0]})"),
              R"(scene.json: sources[0].type: unknown source type "laser" (known: beam, ray, point))");
    EXPECT_EQ(shapeError(R"({"center": [0, 0, 0], "radius": 1, "medium": "water"})"),
              R"(scene.json: shapes[0]: missing required key "type")");
}

TEST(SceneError, RadiusMustBePositive) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": -1, "medium": "water"})"),
              "scene.json: shapes[0].radius: must be > 0");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0, "medium": "water"})"),
              "scene.json: shapes[0].radius: must be > 0");
    EXPECT_EQ(sourceError(R"({"type": "beam", "origin": [0, 0, 0], "direction": [0, 0, 1], "radius": -2})"),
              "scene.json: sources[0].radius: must be > 0");
}

TEST(SceneError, SemiAxesMustBePositive) {
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "semi_axes": [1, 2, 0], "medium": "water"})"),
              "scene.json: shapes[0].semi_axes[2]: must be > 0");
}

TEST(SceneError, EllipsoidMatrixMustBeSymmetricPositiveDefinite) {
    // The geometry's own message, wrapped with the path of the matrix.
    const std::string notSymmetric = shapeError(
        R"({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]],
            "medium": "water"})");
    EXPECT_TRUE(notSymmetric.starts_with("scene.json: shapes[0].matrix: ")) << notSymmetric;
    EXPECT_NE(notSymmetric.find("not symmetric"), std::string::npos) << notSymmetric;
    const std::string notPositive = shapeError(
        R"({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0, 0], [0, -2, 0], [0, 0, 1]],
            "medium": "water"})");
    EXPECT_TRUE(notPositive.starts_with("scene.json: shapes[0].matrix: ")) << notPositive;
    EXPECT_NE(notPositive.find("not positive definite"), std::string::npos) << notPositive;
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0, 0], [0, 1, 0]],
                            "medium": "water"})"),
              "scene.json: shapes[0].matrix: expected a 3x3 matrix (an array of 3 rows of 3 numbers), got 2 elements");
}

TEST(SceneError, EllipsoidTakesSemiAxesOrMatrix) {
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "semi_axes": [1, 1, 1],
                            "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "medium": "water"})"),
              R"(scene.json: shapes[0]: give either "semi_axes" or "matrix", not both)");
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "medium": "water"})"),
              R"(scene.json: shapes[0]: missing required key "semi_axes" or "matrix")");
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
                            "rotation": {"axis": [0, 0, 1], "angle_deg": 10}, "medium": "water"})"),
              R"(scene.json: shapes[0].rotation: applies only with "semi_axes" (a "matrix" is already rotated))");
}

TEST(SceneError, RotationAxisMustBeNonZero) {
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "semi_axes": [1, 2, 3],
                            "rotation": {"axis": [0, 0, 0], "angle_deg": 10}, "medium": "water"})"),
              "scene.json: shapes[0].rotation.axis: must be a non-zero vector");
    EXPECT_EQ(shapeError(R"({"type": "ellipsoid", "center": [0, 0, 0], "semi_axes": [1, 2, 3],
                            "rotation": {"axis": [0, 0, 1], "angle": 10}, "medium": "water"})"),
              R"(scene.json: shapes[0].rotation: unknown key "angle" (valid keys: axis, angle_deg))");
}

TEST(SceneError, BoxMinMustBeBelowMaxOnEveryAxis) {
    EXPECT_EQ(shapeError(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 0], "medium": "water"})"),
              R"(scene.json: shapes[0].max: must be > "min" on every axis (z: max 0 <= min 0))");
    EXPECT_EQ(shapeError(R"({"type": "box", "min": [0, 2.5, 0], "max": [1, 1, 1], "medium": "water"})"),
              R"(scene.json: shapes[0].max: must be > "min" on every axis (y: max 1 <= min 2.5))");
}

TEST(SceneError, DirectionMustBeNonZero) {
    EXPECT_EQ(sourceError(R"({"type": "ray", "origin": [0, 0, 0], "direction": [0, 0, 0]})"),
              "scene.json: sources[0].direction: must be a non-zero vector");
}

TEST(SceneError, WrongTypesAndLengths) {
    // JSON has no NaN literal; a string (or null) where a number belongs is the nearest thing.
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": "NaN", "medium": "water"})"),
              "scene.json: shapes[0].radius: expected a number, got string");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, null, 0], "radius": 1, "medium": "water"})"),
              "scene.json: shapes[0].center[1]: expected a number, got null");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0], "radius": 1, "medium": "water"})"),
              "scene.json: shapes[0].center: expected an array of 3 numbers, got 2 elements");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": "origin", "radius": 1, "medium": "water"})"),
              "scene.json: shapes[0].center: expected an array of 3 numbers, got string");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": true, "medium": "water"})"),
              "scene.json: shapes[0].radius: expected a number, got boolean");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "shapes": {}})"), "scene.json: shapes: expected an array, got object");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "shapes": [3]})"),
              "scene.json: shapes[0]: expected an object, got number");
}

TEST(SceneError, MediumReferences) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"})"),
              R"(scene.json: shapes[0].medium: unknown medium "glass" (defined: water, vacuum))");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})"),
              R"(scene.json: shapes[0]: missing required key "medium")");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "ambient": "air", "media": {"water": {"n": 1.333}}})"),
              R"(scene.json: ambient: unknown medium "air" (defined: water))");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "ambient": "air"})"),
              R"(scene.json: ambient: unknown medium "air" (no media are defined))");
}

TEST(SceneError, MediumProperties) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"ink": {"n": 1.3, "kappa": 1e-3, "sigma": 2}}})"),
              R"(scene.json: media.ink.sigma: give either "kappa" or "sigma", not both)");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"ink": {"n": 0}}})"), "scene.json: media.ink.n: must be > 0");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"ink": {"kappa": 0}}})"),
              R"(scene.json: media.ink: missing required key "n")");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"ink": {"n": 1, "kappa": -1e-6}}})"),
              "scene.json: media.ink.kappa: must be >= 0");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"red ink": {"n": 1, "sigma": -1}}})"),
              R"(scene.json: media["red ink"].sigma: must be >= 0)");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "media": {"": {"n": 1}}})"),
              R"(scene.json: media[""]: a medium name must not be empty)");
}

TEST(SceneError, UnitAndWavelength) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "unit": "inch"})"),
              R"(scene.json: unit: unknown unit "inch" (known: m, cm, mm, um, nm))");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "wavelength_nm": 0})"), "scene.json: wavelength_nm: must be > 0");
}

TEST(SceneError, ShapeNames) {
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water", "name": "d"},
                            {"type": "sphere", "center": [5, 0, 0], "radius": 1, "medium": "water", "name": "d"})"),
              R"(scene.json: shapes[1].name: name "d" is already used by shapes[0])");
    EXPECT_EQ(shapeError(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water", "name": ""})"),
              R"(scene.json: shapes[0].name: must not be empty (leave "name" out for an unnamed shape))");
}

}  // namespace
}  // namespace dropscope
