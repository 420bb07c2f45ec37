// "type": "parametric" / "implicit" in scene files: presets, "transform", shared bases, errors.
#include "geometry/implicit/ImplicitPresets.hpp"
#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "scene/GeneralShapeReader.hpp"
#include "scene/JsonDocument.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"
#include "scene/SceneWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

namespace dropscope {
namespace {

using test::sceneErrorOf;
using test::sceneWithShapes;

const std::string kSourceDir = DROPSCOPE_SOURCE_DIR;

// Volumes and extremes of the analytic presets come from quadrature and projected Newton; these
// agree with the closed forms far more closely (see the parametric and implicit suites).
constexpr double kNumericRelative = 1e-8;

TEST(GeneralShapeReader, ReadsTheFormatExample) {
    const Scene scene = parseScene(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": 1,
        "transform": {"scale": [2, 1, 1], "translation": [0, 0, 5]}, "medium": "water"})"),
                                   "scene.json");
    ASSERT_EQ(scene.shapes.size(), 1u);
    const Shape& shape = *scene.shapes[0];
    EXPECT_EQ(shape.kind(), ShapeKind::Parametric);
    EXPECT_EQ(scene.mediumOf(shape).name, "water");
    EXPECT_NEAR(shape.xMin(), -2.0, kNumericRelative);
    EXPECT_NEAR(shape.xMax(), 2.0, kNumericRelative);
    EXPECT_NEAR(shape.zMin(), 4.0, kNumericRelative);
    EXPECT_NEAR(shape.zMax(), 6.0, kNumericRelative);
    EXPECT_NEAR(shape.volume(), 4.0 / 3.0 * std::numbers::pi * 2.0, kNumericRelative * 10);
}

TEST(GeneralShapeReader, AppliesTheTransformStepsInTheDocumentedOrder) {
    // Steps that do not commute, listed in the file in reverse: the product must be
    // matrix . reflection . shear . rotation . scale, then + translation.
    const Scene scene = parseScene(sceneWithShapes(R"({"type": "implicit", "preset": "superellipsoid",
        "semi_axes": [1, 1, 1], "exponents": [1, 1], "medium": "water", "transform": {
        "translation": [0, 0, 10], "matrix": [[1, 2, 0], [0, 1, 0], [0, 0, 1]], "reflection": {"normal": [1, 1, 0]},
        "shear": {"xz": 0.5}, "rotation": {"axis": [0, 0, 1], "angle_deg": 90}, "scale": [3, 1, 2]}})"),
                                   "scene.json");
    const auto& shape = static_cast<const GeneralShape&>(*scene.shapes[0]);
    Eigen::Matrix3d matrix, reflection, shear, rotation;
    matrix << 1, 2, 0, 0, 1, 0, 0, 0, 1;
    reflection << 0, -1, 0, -1, 0, 0, 0, 0, 1;  // I - 2 n n^T, n = (1, 1, 0)/sqrt(2)
    shear << 1, 0, 0.5, 0, 1, 0, 0, 0, 1;
    rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    const Eigen::Matrix3d expected = matrix * reflection * shear * rotation * Eigen::Vector3d(3, 1, 2).asDiagonal();
    EXPECT_LE((shape.transform().matrix() - expected).cwiseAbs().maxCoeff(), 1e-14) << shape.transform().matrix();
    EXPECT_EQ(shape.transform().translation(), Eigen::Vector3d(0, 0, 10));
}

TEST(GeneralShapeReader, EqualPresetsShareOneBase) {
    const Scene scene = parseScene(sceneWithShapes(R"(
        {"type": "parametric", "preset": "torus", "major_radius": 1, "minor_radius": 0.25, "medium": "water"},
        {"type": "parametric", "preset": "torus", "major_radius": 1, "minor_radius": 0.25, "medium": "water",
         "transform": {"translation": [5, 0, 0]}},
        {"type": "parametric", "preset": "torus", "major_radius": 1, "minor_radius": 0.3, "medium": "water",
         "transform": {"translation": [-5, 0, 0]}},
        {"type": "implicit", "preset": "blob", "centers": [[0, 0, 5], [1, 0, 5]], "radii": [0.6, 0.6], "blend": 0.1,
         "medium": "water"},
        {"type": "implicit", "preset": "blob", "centers": [[0, 0, 5], [1, 0, 5]], "radii": [0.6, 0.6], "blend": 0.1,
         "medium": "water", "transform": {"translation": [0, 0, 5]}})"),
                                   "scene.json");
    ASSERT_EQ(scene.shapes.size(), 5u);
    const auto parametric = [&](std::size_t i) { return static_cast<const ParametricShape&>(*scene.shapes[i]).base(); };
    const auto implicit = [&](std::size_t i) { return static_cast<const ImplicitShape&>(*scene.shapes[i]).base(); };
    EXPECT_EQ(parametric(0), parametric(1));
    EXPECT_NE(parametric(0), parametric(2));
    EXPECT_EQ(implicit(3), implicit(4));
    EXPECT_NEAR(scene.shapes[0]->volume(), 2.0 * std::numbers::pi * std::numbers::pi * 0.0625, 1e-8);
}

TEST(GeneralShapeReader, ReadsBezierPatchesFromAnAssetFile) {
    // Relative to the scene file's folder.
    const std::string scene = R"({"dropscope": 1, "media": {"water": {"n": 1.333}}, "shapes": [
        {"type": "parametric", "preset": "bezier", "patches": "../shapes/flattened_droplet.json", "medium": "water"}]})";
    const Scene loaded = parseScene(scene, kSourceDir + "/assets/scenes/inline.json");
    ASSERT_EQ(loaded.shapes.size(), 1u);
    EXPECT_GT(loaded.shapes[0]->volume(), 0.0);
    // Written back inline, it reads again as the same surface.
    const Scene reloaded = parseScene(sceneToJson(loaded), "written.json");
    const auto& a = static_cast<const GeneralShape&>(*loaded.shapes[0]);
    const auto& b = static_cast<const GeneralShape&>(*reloaded.shapes[0]);
    EXPECT_TRUE(a.presetParameters() == b.presetParameters());
    EXPECT_EQ(a.volume(), b.volume());
}

TEST(GeneralShapeReader, ReadsAPatchesFileFromItsText) {
    // The text entry point the fuzzer drives (tests/fuzz) reads the asset as the scene's "patches" does.
    std::ifstream in(kSourceDir + "/assets/shapes/flattened_droplet.json");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(parseBezierPatchesFile(text, "patches.json")->presetName(), "bezier");
    try {
        parseBezierPatchesFile(R"({"patches": [], "scale": 2})", "patches.json");
        ADD_FAILURE() << "an unknown key was accepted";
    } catch (const SceneError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("patches.json: ", 0), 0u) << message;
        EXPECT_NE(message.find(R"(unknown key "scale")"), std::string::npos) << message;
    }
}

TEST(GeneralShapeReader, ErrorsNameTheValue) {
    EXPECT_EQ(
        sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "cube", "medium": "water"})")),
        R"(scene.json: shapes[0].preset: unknown parametric preset "cube" (known: sphere, ellipsoid, torus, bezier))");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "implicit", "preset": "torus", "medium": "water"})")),
              R"(scene.json: shapes[0].preset: unknown implicit preset "torus" (known: superellipsoid, blob))");
    EXPECT_EQ(
        sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": -1, "medium": "water"})")),
        "scene.json: shapes[0].radius: must be > 0");
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "torus", "major_radius": 1,
        "minor_radius": 2, "medium": "water"})"))
                  .find("scene.json: shapes[0].minor_radius: "),
              std::string::npos);
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": 1, "medium": "water",
        "transform": {"scale": [1, 0, 1]}})"))
                  .find("scene.json: shapes[0].transform.scale: scale factors must be"),
              std::string::npos);
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": 1, "medium": "water",
        "transform": {"shear": {"xy": 1, "yx": 1}}})"))
                  .find("scene.json: shapes[0].transform.shear: transformation matrix is singular"),
              std::string::npos);
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": 1, "medium": "water",
        "transform": {"scael": 2}})")),
              R"(scene.json: shapes[0].transform: unknown key "scael" (did you mean "scale"?))");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "implicit", "preset": "blob", "centers": [[0, 0, 0], [1, 0, 0]],
        "radii": [1], "blend": 0.1, "medium": "water"})")),
              "scene.json: shapes[0].radii: must give one radius per center (2 centers, 1 radii)");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "bezier", "patches": "no/such.json",
        "medium": "water"})")),
              "scene.json: shapes[0].patches: in the patches file: no/such.json: no such file");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "bezier", "patches": "",
        "medium": "water"})")),
              R"(scene.json: shapes[0].patches: must be the patches or the name of a file holding them, not "")");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "implicit", "preset": "blob", "centers": [[0, 0, 0]],
        "radii": [1], "blend": 0.1, "medium": "water"})"))
                  .rfind("scene.json: shapes[0].centers: ", 0),
              0u);
    // Parameters at the edge of the double range give no usable shape: refused, not NaN volumes.
    EXPECT_NE(
        sceneErrorOf(sceneWithShapes(R"({"type": "implicit", "preset": "superellipsoid", "semi_axes": [1e300, 1, 1],
        "exponents": [1, 1], "medium": "water"})"))
            .find("scene.json: shapes[0]: "),
        std::string::npos);
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "sphere", "radius": 1, "medium": "water",
        "transform": {"scale": 1e200}})"))
                  .find("scene.json: shapes[0]"),
              std::string::npos);
    // Droplets far below the tessellation's resolution leave no surface to draw or to test overlaps with.
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "implicit", "preset": "blob", "centers": [[0, 0, 0], [1, 1, 1]],
        "radii": [0.001, 0.001], "blend": 0.0001, "medium": "water"})"))
                  .find("scene.json: shapes[0]"),
              std::string::npos);
    EXPECT_NE(sceneErrorOf(sceneWithShapes(R"({"type": "parametric", "preset": "bezier", "patches": [[[[[0, 0, 0]]]]],
        "medium": "water"})"))
                  .find("scene.json: shapes[0].patches[0][0]: must be 4 rows"),
              std::string::npos);
}

// The implicit shapes' load time is bounded before any is built (kMaxBlobSpheres, kMaxImplicitBases): the
// refusal of 1001 distinct bases comes without integrating the 1000 before it.
TEST(GeneralShapeReader, ImplicitLoadWorkIsBoundedBeforeAnythingIsBuilt) {
    const auto blob = [](std::size_t spheres, std::size_t radiusCount) {
        std::string centers;
        std::string radii;
        for (std::size_t i = 0; i < spheres; ++i) centers += (i ? ", [" : "[") + std::to_string(i) + ", 0, 0]";
        for (std::size_t i = 0; i < radiusCount; ++i) radii += i ? ", 0.6" : "0.6";
        return R"({"type": "implicit", "preset": "blob", "centers": [)" + centers + R"(], "radii": [)" + radii +
               R"(], "blend": 0.1, "medium": "water"})";
    };
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(blob(kMaxBlobSpheres + 1, kMaxBlobSpheres + 1))),
              "scene.json: shapes[0].centers: a blob has at most 64 spheres, got 65 (its load and trace time grow "
              "with the square of their number); model more droplets as separate shapes or a droplet cloud "
              "(docs/limits.md)");
    // 64 are read (and refused here for the radii, before the blob would be built).
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(blob(kMaxBlobSpheres, kMaxBlobSpheres - 1))),
              "scene.json: shapes[0].radii: must give one radius per center (64 centers, 63 radii)");

    // 48 distinct blobs of 64 spheres are estimated at 148 s, the 49th crosses the 150 s limit. Each differs in
    // one sphere's position only.
    const auto blobs = [](std::size_t count) {
        std::string shapes;
        for (std::size_t b = 0; b < count; ++b) {
            std::string centers;
            std::string radii;
            for (std::size_t i = 0; i < kMaxBlobSpheres; ++i) {
                centers += (i ? ", [" : "[") + std::to_string(i) + ", " + (i ? "0" : std::to_string(b)) + ", 0]";
                radii += i ? ", 0.6" : "0.6";
            }
            shapes += (b ? ", " : "") + std::string(R"({"type": "implicit", "preset": "blob", "centers": [)") +
                      centers + R"(], "radii": [)" + radii + R"(], "blend": 0.1, "medium": "water"})";
        }
        return shapes;
    };
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(blobs(49))),
              "scene.json: shapes[48]: the scene's implicit shapes up to this one would take about 152 s to load, "
              "more than the limit of 150 s (each distinct preset and parameters is integrated once: about 0.13 s "
              "for a superellipsoid, 3.1 s for a blob of 64 spheres); shapes that differ only in transform share "
              "one, so vary the transform's scale instead of the parameters (docs/limits.md)");
    // Shapes differing only in placement, medium or name share one base, also where the parameters are
    // written differently (1 and 1.0, another key order): 2000 superellipsoids, one base.
    std::string same;
    for (int i = 0; i < 2000; ++i) {
        same += (i ? ", " : "") +
                std::string(i % 2 ? R"({"type": "implicit", "preset": "superellipsoid", )"
                                    R"("semi_axes": [1, 1, 1], "exponents": [0.5, 0.5], )"
                                  : R"({"exponents": [5e-1, 0.50], "semi_axes": [1.0, 1e0, 1], )"
                                    R"("preset": "superellipsoid", "type": "implicit", )") +
                R"("medium": "water", "transform": {"translation": [)" + std::to_string(5 * i) + R"(, 0, 0]}})";
    }
    const std::string origin = "scene.json";
    const Json sharing = parseJsonDocument("[" + same + "]", origin);
    EXPECT_NO_THROW(checkImplicitLoadTime(JsonReader(sharing, "shapes", origin)));
    // A shape the reader refuses is left to it, in the file's order.
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "sphere", "center": [0, 0, 0], "radius": -1, "medium": "water"},
        {"type": "implicit", "preset": "blob", "centers": [[0, 0, 0]], "radii": [1], "blend": 0.1, "medium": "water"})"))
                  .rfind("scene.json: shapes[0].radius: ", 0),
              0u);
    EXPECT_NEAR(implicitLoadSeconds(*makeSuperellipsoid(Eigen::Vector3d(1, 1, 1), Eigen::Vector2d(1, 1))), 0.13, 1e-12);
}

TEST(GeneralShapeReader, OverlappingShapesAreRefusedAndAShapeInATorusHoleIsNot) {
    const std::string torus = R"({"type": "parametric", "preset": "torus", "major_radius": 2, "minor_radius": 0.5,
        "medium": "water", "name": "ring"})";
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(torus + R"(, {"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "medium": "water"})")),
              "no error");
    const std::string error = sceneErrorOf(sceneWithShapes(torus + R"(, {"type": "sphere", "center": [2, 0, 0.6],
        "radius": 0.3, "medium": "water"})"));
    EXPECT_NE(error.find("shapes[1]"), std::string::npos) << error;
    EXPECT_NE(error.find("overlap"), std::string::npos) << error;
}

}  // namespace
}  // namespace dropscope
