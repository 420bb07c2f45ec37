// docs/limits.md: every derived quantity of a loaded scene is finite and within the limits, or the loader
// refuses it naming the shape, source or detector.
#include "scene/SceneLimits.hpp"

#include "geometry/Box.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using test::sceneErrorOf;
using test::sceneWithShapes;

std::string sphere(const std::string& center, const std::string& radius) {
    return R"({"type": "sphere", "center": )" + center + R"(, "radius": )" + radius + R"(, "medium": "water"})";
}

std::string withSource(const std::string& shapes, const std::string& source) {
    return R"({"dropscope": 1, "media": {"water": {"n": 1.333}}, "shapes": [)" + shapes + R"(], "sources": [)" +
           source + "]}";
}

TEST(SmallestFeature, IsThreeVolumesOverTheArea) {
    EXPECT_DOUBLE_EQ(smallestFeature(Sphere({0, 0, 0}, 2.5)), 2.5);
    EXPECT_DOUBLE_EQ(smallestFeature(Box({0, 0, 0}, {2, 2, 2})), 1.0);
    // A plate 1e-3 thick: 3 * 1e-3 / (2 + 4e-3).
    EXPECT_NEAR(smallestFeature(Box({0, 0, 0}, {1, 1, 1e-3})), 3e-3 / 2.004, 1e-15);
}

// The issue's report: radius 1e308 was accepted with an infinite volume.
TEST(SceneLimits, HugeSphereIsRefusedNamingIt) {
    EXPECT_EQ(shapeLimitProblem(Sphere({0, 0, 0}, 1e308)).value_or("none"),
              "its bounds reach 1e+308, beyond the limit 1e+100 on any coordinate (docs/limits.md)");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(sphere("[0, 0, 0]", "1e308"))),
              "scene.json: shapes[0]: its bounds reach 1e+308, beyond the limit 1e+100 on any coordinate "
              "(docs/limits.md)");
}

// The issue's report: a torus moved to x = 1e300 gave exit 1, "internal error: box corners must be finite".
TEST(SceneLimits, FarTorusIsRefusedNamingIt) {
    const std::string torus = R"({"type": "parametric", "preset": "torus", "major_radius": 1, "minor_radius": 0.3,
        "transform": {"translation": [1e300, 0, 0]}, "medium": "water"})";
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(torus)),
              "scene.json: shapes[0]: its bounds reach 1e+300, beyond the limit 1e+100 on any coordinate "
              "(docs/limits.md)");
}

TEST(SceneLimits, VanishingVolumeIsRefused) {
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(sphere("[0, 0, 0]", "1e-110"))),
              "scene.json: shapes[0]: its volume is 0, not finite and > 0 (docs/limits.md)");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(sphere("[0, 0, 0]", "1e-101"))),
              "scene.json: shapes[0]: its smallest feature (3 volume / area) 1e-101 is below the limit 1e-100 "
              "(docs/limits.md)");
}

TEST(SceneLimits, BoxCornersBeyondTheLimitNameTheKey) {
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(R"({"type": "box", "min": [0, 0, 0], "max": [1e101, 1, 1],
        "medium": "water"})")),
              "scene.json: shapes[0].max: beyond the limit 1e+100 on any coordinate (docs/limits.md)");
}

// Reach over smallest feature: 1e12 passes, just above it is refused, naming the finest shape and what
// reaches farthest.
TEST(SceneLimits, ScaleRatioIsAtMostOneTrillion) {
    const std::string pair = sphere("[0, 0, 0]", "1e-3") + ", " + sphere("[0.999e9, 0, 0]", "1");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(pair)), "no error");  // reach 0.999e9 + 1 over 1e-3: 0.999e12 + 1e3
    const std::string far = sphere("[0, 0, 0]", "1e-3") + ", " + sphere("[1.1e9, 0, 0]", "1");
    EXPECT_EQ(sceneErrorOf(sceneWithShapes(far)),
              "scene.json: shapes[0]: sphere: its smallest feature (3 volume / area) 0.001 mm is 1.1e+12 times "
              "smaller than the scene's reach 1.1e+09 mm (shapes[1]: sphere); the limit is 1e+12, beyond which "
              "double precision cannot tell its surface from its inside (docs/limits.md)");
}

TEST(SceneLimits, DistantSourceCountsInTheReach) {
    const std::string near = R"({"type": "ray", "origin": [-1e8, 0, 0], "direction": [1, 0, 0]})";
    EXPECT_EQ(sceneErrorOf(withSource(sphere("[0, 0, 0]", "1e-3"), near)), "no error");
    const std::string far = R"({"type": "beam", "origin": [-1e10, 0, 0], "direction": [1, 0, 0], "radius": 1})";
    const std::string error = sceneErrorOf(withSource(sphere("[0, 0, 0]", "1e-3"), far));
    EXPECT_NE(error.find("scene.json: shapes[0]: sphere: its smallest feature"), std::string::npos) << error;
    EXPECT_NE(error.find("reach 1e+10 mm (sources[0])"), std::string::npos) << error;
    const std::string beyond = R"({"type": "beam", "origin": [0, 0, 0], "direction": [1, 0, 0], "radius": 1e200})";
    EXPECT_EQ(sceneErrorOf(withSource(sphere("[5, 0, 0]", "1"), beyond)),
              "scene.json: sources[0]: it reaches 1e+200 (origin plus radius), beyond the limit 1e+100 on any "
              "coordinate (docs/limits.md)");
}

TEST(SceneLimits, ViewBeyondTheLimitNamesTheKey) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "view": {"eye": [1e300, 0, 0], "target": [0, 0, 0]}})"),
              "scene.json: view.eye: beyond the limit 1e+100 on any coordinate (docs/limits.md)");
}

TEST(SceneLimits, GeneratedDropletsAreNamedByTheirGenerator) {
    // Droplets of radius 1e-3 in a region 1e5 from the origin pass the generator's own 1e-9 check, and the
    // ray source at 2e9 then breaks the scale limit.
    const std::string scene = R"({"dropscope": 1, "media": {"water": {"n": 1.333}},
        "generators": [{"type": "droplet_cloud", "region": {"min": [1e5, 0, 0], "max": [100010, 10, 10]},
                        "count": 3, "radius": {"distribution": "fixed", "value": 1e-3}, "medium": "water"}],
        "sources": [{"type": "ray", "origin": [-2e9, 0, 0], "direction": [1, 0, 0]}]})";
    const std::string error = sceneErrorOf(scene);
    EXPECT_EQ(error.rfind("scene.json: generators[0]: droplet ", 0), 0u) << error;
    EXPECT_NE(error.find("reach 2e+09 mm (sources[0])"), std::string::npos) << error;
}

// The labels the loss warning and first_lost.shape_label give shapes by their octree id.
TEST(SceneLimits, ShapeLabelsNameTheFileEntry) {
    const Scene scene = parseScene(R"({"dropscope": 1, "media": {"water": {"n": 1.333}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water", "name": "d"},
                   {"type": "box", "min": [5, 5, 5], "max": [6, 6, 6], "medium": "water"}],
        "generators": [{"type": "droplet_cloud", "region": {"min": [10, 0, 0], "max": [20, 10, 10]},
                        "count": 3, "radius": {"distribution": "fixed", "value": 0.5}, "medium": "water"}]})",
                                   "scene.json");
    ASSERT_EQ(scene.shapes.size(), 5u);
    EXPECT_EQ(shapeLabel(scene, 0), R"(shapes[0]: sphere "d")");
    EXPECT_EQ(shapeLabel(scene, 1), "shapes[1]: box");
    EXPECT_EQ(shapeLabel(scene, 2), "generators[0]: droplet 0");
    EXPECT_EQ(shapeLabel(scene, 4), "generators[0]: droplet 2");
    EXPECT_EQ(shapeLabel(scene, 5), "shape 5");
}

}  // namespace
}  // namespace dropscope
