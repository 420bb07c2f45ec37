// writeScene / sceneToJson: what they write reads back (parseScene) as the same scene.
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/SceneWriter.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace dropscope {
namespace {

const std::string kDataDir = DROPSCOPE_TEST_DATA_DIR;
const std::string kSourceDir = DROPSCOPE_SOURCE_DIR;

// An ellipsoid is written as centre, semi-axes and rotation, recovered from the eigenvectors of its
// matrix: the reloaded matrix differs by the eigensolver's and the rotation's rounding, a few ulps of
// its largest entry.
constexpr double kEllipsoidMatrixRelative = 1e-12;
// Directions (source directions, view up) are normalised again when read; a unit vector renormalised
// moves by at most a few ulps.
constexpr double kRenormalisedDirection = 4.0 * std::numeric_limits<double>::epsilon();

void expectSameShape(const Shape& actual, const Shape& expected, std::size_t id) {
    SCOPED_TRACE("shape " + std::to_string(id));
    ASSERT_EQ(actual.kind(), expected.kind());
    EXPECT_EQ(actual.mediumId(), expected.mediumId());
    switch (expected.kind()) {
    case ShapeKind::Sphere: {
        const auto& a = static_cast<const Sphere&>(actual);
        const auto& e = static_cast<const Sphere&>(expected);
        EXPECT_EQ(a.center(), e.center());
        EXPECT_EQ(a.radius(), e.radius());
        break;
    }
    case ShapeKind::Box: {
        const auto& a = static_cast<const Box&>(actual);
        const auto& e = static_cast<const Box&>(expected);
        EXPECT_EQ(a.lower(), e.lower());
        EXPECT_EQ(a.upper(), e.upper());
        break;
    }
    case ShapeKind::Ellipsoid: {
        const auto& a = static_cast<const Ellipsoid&>(actual);
        const auto& e = static_cast<const Ellipsoid&>(expected);
        EXPECT_EQ(a.center(), e.center());
        const double scale = e.matrix().cwiseAbs().maxCoeff();
        EXPECT_LE((a.matrix() - e.matrix()).cwiseAbs().maxCoeff(), kEllipsoidMatrixRelative * scale)
            << "written " << e.matrix() << "\nread back " << a.matrix();
        break;
    }
    case ShapeKind::Parametric:
    case ShapeKind::Implicit: {
        // Written as the composed matrix and translation: the same transform, bit for bit.
        const auto& a = static_cast<const GeneralShape&>(actual);
        const auto& e = static_cast<const GeneralShape&>(expected);
        EXPECT_EQ(a.presetName(), e.presetName());
        EXPECT_TRUE(a.presetParameters() == e.presetParameters());
        EXPECT_EQ(a.transform().matrix(), e.transform().matrix());
        EXPECT_EQ(a.transform().translation(), e.transform().translation());
        break;
    }
    }
}

void expectSameDirection(const Direction& actual, const Direction& expected) {
    EXPECT_LE((actual.vector() - expected.vector()).cwiseAbs().maxCoeff(), kRenormalisedDirection);
}

void expectSameScene(const Scene& actual, const Scene& expected) {
    EXPECT_EQ(actual.formatVersion, 1);
    EXPECT_EQ(actual.unit, expected.unit);
    EXPECT_EQ(actual.unitInMetres, expected.unitInMetres);
    EXPECT_EQ(actual.wavelengthNm, expected.wavelengthNm);
    EXPECT_EQ(actual.ambient, expected.ambient);
    ASSERT_EQ(actual.media.size(), expected.media.size());
    for (std::size_t i = 0; i < expected.media.size(); ++i) {
        SCOPED_TRACE("medium " + expected.media[i].name);
        EXPECT_EQ(actual.media[i].name, expected.media[i].name);
        EXPECT_EQ(actual.media[i].n, expected.media[i].n);
        EXPECT_EQ(actual.media[i].kappa, expected.media[i].kappa);
        EXPECT_EQ(actual.media[i].sigma, expected.media[i].sigma);
        EXPECT_EQ(actual.media[i].absorptionPerUnit, expected.media[i].absorptionPerUnit);
    }
    ASSERT_EQ(actual.shapes.size(), expected.shapes.size());
    EXPECT_EQ(actual.explicitShapeCount, expected.shapes.size());  // generated shapes come back explicit
    EXPECT_EQ(actual.shapeNames, expected.shapeNames);
    for (std::size_t id = 0; id < expected.shapes.size(); ++id) {
        expectSameShape(*actual.shapes[id], *expected.shapes[id], id);
    }
    ASSERT_EQ(actual.sources.size(), expected.sources.size());
    for (std::size_t i = 0; i < expected.sources.size(); ++i) {
        SCOPED_TRACE("source " + std::to_string(i));
        EXPECT_EQ(actual.sources[i].type, expected.sources[i].type);
        EXPECT_EQ(actual.sources[i].origin, expected.sources[i].origin);
        EXPECT_EQ(actual.sources[i].radius, expected.sources[i].radius);
        if (expected.sources[i].type != SourceType::PointSource) {
            expectSameDirection(actual.sources[i].direction, expected.sources[i].direction);
        }
        EXPECT_EQ(actual.sources[i].polarisation, expected.sources[i].polarisation);  // numbers written exactly
    }
    EXPECT_EQ(actual.octree.maxDepth, expected.octree.maxDepth);
    EXPECT_EQ(actual.octree.maxShapesPerLeaf, expected.octree.maxShapesPerLeaf);
    ASSERT_EQ(actual.view.has_value(), expected.view.has_value());
    if (expected.view) {
        EXPECT_EQ(actual.view->eye, expected.view->eye);
        EXPECT_EQ(actual.view->target, expected.view->target);
        expectSameDirection(actual.view->up, expected.view->up);
        EXPECT_EQ(actual.view->fovDeg, expected.view->fovDeg);
    }
}

void expectRoundTrip(const Scene& scene) {
    const std::string text = sceneToJson(scene);
    Scene reloaded;
    ASSERT_NO_THROW(reloaded = parseScene(text, "written.json")) << text;
    expectSameScene(reloaded, scene);
}

// The full example of docs/scene-format.md, as SceneLoader.LoadsTheFullExampleOfTheFormatDocument reads it.
std::string formatDocumentExample() {
    std::ifstream in(kSourceDir + "/docs/scene-format.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string document = text.str();
    const auto begin = document.find("```json\n");
    const auto end = document.find("```", begin + 8);
    if (begin == std::string::npos || end == std::string::npos) return {};
    return document.substr(begin + 8, end - begin - 8);
}

TEST(SceneWriter, RoundTripsEveryBundledAndTestScene) {
    std::vector<std::filesystem::path> files;  // assets/scenes/default.json among them
    for (const auto& folder : {kDataDir + "/scenes", kDataDir + "/scenes/golden", kSourceDir + "/assets/scenes",
                               kSourceDir + "/assets/scenes/validation"}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const std::string name = entry.path().filename().string();
            if (entry.path().extension() != ".json" || name == "malformed.json" || name == "overlapping.json") continue;
            files.push_back(entry.path());
        }
    }
    EXPECT_GE(files.size(), 15u);
    for (const auto& file : files) {
        SCOPED_TRACE(file.string());
        expectRoundTrip(loadScene(file));
    }
}

TEST(SceneWriter, RoundTripsTheFullExampleOfTheFormatDocument) {
    const std::string example = formatDocumentExample();
    ASSERT_FALSE(example.empty());
    const Scene scene = parseScene(example, "docs/scene-format.md");
    ASSERT_GT(scene.shapes.size(), scene.explicitShapeCount);  // the example has a generator
    expectRoundTrip(scene);
    EXPECT_EQ(sceneToJson(scene).find("generators"), std::string::npos);
}

TEST(SceneWriter, WritesTheBuiltInVacuumSoMediumIdsStay) {
    const Scene scene = parseScene(R"({"dropscope": 1, "media": {"water": {"n": 1.333}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "vacuum"}]})",
                                   "scene.json");
    ASSERT_EQ(scene.media.size(), 2u);  // water, then the built-in vacuum
    expectRoundTrip(scene);
}

TEST(SceneWriter, RandomRotatedEllipsoidsKeepTheirMatrices) {
    for (int i = 0; i < 200; ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        testing::Rng rng(static_cast<std::uint64_t>(i));
        Scene scene;
        scene.media.push_back({"vacuum", 1.0, {}, {}, 0.0});
        // Semi-axes up to 1e5 times each other, far from the origin too.
        const Eigen::Vector3d semiAxes(std::pow(10.0, testing::uniform(rng, -2.5, 2.5)),
                                       std::pow(10.0, testing::uniform(rng, -2.5, 2.5)),
                                       std::pow(10.0, testing::uniform(rng, -2.5, 2.5)));
        scene.shapes.push_back(std::make_unique<Ellipsoid>(
            Ellipsoid::fromSemiAxes(testing::randomPoint(rng, 1e4), semiAxes, testing::randomRotation(rng))));
        scene.shapeNames.emplace_back();
        expectRoundTrip(scene);
    }
}

TEST(SceneWriter, AnUnrotatedEllipsoidHasNoRotationKey) {
    const Scene scene = parseScene(R"({"dropscope": 1, "shapes": [{"type": "ellipsoid", "center": [0, 0, 0],
        "semi_axes": [0.5, 1, 1.5], "medium": "vacuum"}]})",
                                   "scene.json");
    const std::string text = sceneToJson(scene);
    EXPECT_EQ(text.find("rotation"), std::string::npos) << text;
    expectRoundTrip(scene);
}

TEST(SceneWriter, IsIndentedWithOneShapePerLine) {
    const Scene scene = loadScene(kSourceDir + "/assets/scenes/default.json");
    const std::string text = sceneToJson(scene);
    EXPECT_EQ(text.rfind("{\n  \"dropscope\": 1,\n  \"unit\": \"mm\",\n", 0), 0u) << text;
    EXPECT_NE(text.find("\n    {\"type\": \"sphere\", \"name\": \"drop-a\", \"center\": [0.0, 0.0, 0.0], "
                        "\"radius\": 0.8, \"medium\": \"water\"},\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\n    \"water\": {\"n\": 1.3337, \"kappa\": 1.9e-09},\n"), std::string::npos) << text;
    EXPECT_EQ(text.back(), '\n');
}

TEST(SceneWriter, RefusesScenesNoFileCouldExpress) {
    Scene scene;
    scene.media.push_back({"water", 1.33, {}, {}, 0.0});
    scene.media.push_back({"water", 1.5, {}, {}, 0.0});
    EXPECT_THROW(sceneToJson(scene), std::invalid_argument);
    scene.media.pop_back();
    scene.shapes.push_back(std::make_unique<Sphere>(Point::Zero(), 1.0));
    scene.shapes.back()->setMediumId(3);
    scene.shapeNames.emplace_back();
    EXPECT_THROW(sceneToJson(scene), std::invalid_argument);
}

// The pairwise definition of checkShapesDisjoint's answer, O(N^2): the first later shape (in id order)
// that partly overlaps an earlier one, with the first such earlier one.
std::string bruteForceOverlapError(const Scene& scene) {
    for (std::size_t later = 1; later < scene.shapes.size(); ++later) {
        for (std::size_t earlier = 0; earlier < later; ++earlier) {
            const Shape& a = *scene.shapes[earlier];
            const Shape& b = *scene.shapes[later];
            if (!a.overlaps(b) || nestsInside(a, b) || nestsInside(b, a)) continue;
            return jsonpath::element("shapes", later) + " overlaps " + jsonpath::element("shapes", earlier);
        }
    }
    return "no error";
}

std::string overlapErrorOf(const Scene& scene) {
    try {
        checkShapesDisjoint(scene);
    } catch (const SceneError& error) {
        const std::string detail = error.jsonPath() + " " + error.detail();
        // "shapes[7] box overlaps shapes[2] (...)" -> "shapes[7] overlaps shapes[2]"
        const auto overlaps = detail.find(" overlaps ");
        const auto end = detail.find(' ', overlaps + 10);
        return error.jsonPath() + detail.substr(overlaps, end - overlaps);
    }
    return "no error";
}

TEST(SceneWriter, OverlapCheckOfManyShapesAgreesWithThePairwiseDefinition) {
    // Mixed kinds and sizes (several size classes, every 20th shape 8 times larger: a host for nesting or
    // a large overlapper), dense enough that most scenes overlap somewhere and some do not.
    int withOverlap = 0;
    constexpr int kCases = 40;
    for (int i = 0; i < kCases; ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        testing::Rng rng(static_cast<std::uint64_t>(1000 + i));
        Scene scene;
        scene.origin = "scene.json";
        const int count = 30 + static_cast<int>(rng() % 120);
        const double halfWidth = 4.0 + 0.25 * i;
        for (int k = 0; k < count; ++k) {
            const double size = std::pow(8.0, testing::uniform(rng, -2.0, 0.0)) * (k % 20 == 0 ? 8.0 : 1.0);
            scene.shapes.push_back(testing::randomShape(rng, k, testing::randomPoint(rng, halfWidth), size));
            scene.shapeNames.emplace_back();
        }
        const std::string expected = bruteForceOverlapError(scene);
        withOverlap += expected != "no error" ? 1 : 0;
        EXPECT_EQ(overlapErrorOf(scene), expected);
    }
    EXPECT_GT(withOverlap, kCases / 4);
    EXPECT_LT(withOverlap, kCases);
}

TEST(SceneWriter, ASavedCloudOf20000SpheresLoadsAsExplicitShapes) {
    // cloud.json generates 20,000 droplets; saved, they are 20,000 explicit shapes that the loader
    // checks pairwise for overlaps.
    const Scene generated = loadScene(kSourceDir + "/assets/scenes/cloud.json");
    ASSERT_EQ(generated.shapes.size(), 20000u);
    ASSERT_EQ(generated.explicitShapeCount, 0u);
    const Scene saved = parseScene(sceneToJson(generated), "saved.json");
    EXPECT_EQ(saved.explicitShapeCount, 20000u);
    expectSameScene(saved, generated);
}

}  // namespace
}  // namespace dropscope
