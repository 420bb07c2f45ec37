// Droplet clouds read from "generators": reproducible, complete, inside their region, disjoint from
// one another and from every other shape, with ids after the explicit shapes.
#include "geometry/Sphere.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/SceneTestSupport.hpp"
#include "tree/Octree.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace dropscope {
namespace {

using test::sceneErrorOf;

// A scene with media "air" (ambient) and "water", the given explicit shapes and generators.
std::string sceneWith(const std::string& shapes, const std::string& generators) {
    return R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1.0003}, "water": {"n": 1.333}},)"
           R"( "shapes": [)" +
           shapes + R"(], "generators": [)" + generators + "]}";
}

// One droplet_cloud over the cube [0, 1]^3 (or `region`), with `amount` ("count": n or
// "volume_fraction": f) and the given radius distribution.
std::string cloud(const std::string& amount, const std::string& radius, int seed = 7,
                  const std::string& region = R"({"min": [0, 0, 0], "max": [1, 1, 1]})") {
    return R"({"type": "droplet_cloud", "region": )" + region + ", " + amount + R"(, "radius": )" + radius +
           R"(, "medium": "water", "seed": )" + std::to_string(seed) + "}";
}

const std::string kLognormal = R"({"distribution": "lognormal", "median": 0.01, "sigma": 0.3})";

const Sphere& sphereAt(const Scene& scene, std::size_t id) { return static_cast<const Sphere&>(*scene.shapes.at(id)); }

std::string generatorError(const std::string& generator) { return sceneErrorOf(sceneWith("", generator)); }

TEST(DropletCloud, SameSeedGivesTheIdenticalCloud) {
    const Scene first = parseScene(sceneWith("", cloud(R"("count": 2000)", kLognormal)), "a.json");
    const Scene second = parseScene(sceneWith("", cloud(R"("count": 2000)", kLognormal)), "b.json");
    ASSERT_EQ(first.shapes.size(), 2000u);
    ASSERT_EQ(second.shapes.size(), 2000u);
    for (std::size_t id = 0; id < first.shapes.size(); ++id) {
        EXPECT_EQ(sphereAt(first, id).center(), sphereAt(second, id).center()) << "droplet " << id;
        EXPECT_EQ(sphereAt(first, id).radius(), sphereAt(second, id).radius()) << "droplet " << id;
    }
}

TEST(DropletCloud, DifferentSeedsGiveDifferentClouds) {
    const Scene first = parseScene(sceneWith("", cloud(R"("count": 100)", kLognormal, 7)), "a.json");
    const Scene second = parseScene(sceneWith("", cloud(R"("count": 100)", kLognormal, 8)), "b.json");
    std::size_t sameCenters = 0;
    std::size_t sameRadii = 0;
    for (std::size_t id = 0; id < 100; ++id) {
        sameCenters += sphereAt(first, id).center() == sphereAt(second, id).center() ? 1 : 0;
        sameRadii += sphereAt(first, id).radius() == sphereAt(second, id).radius() ? 1 : 0;
    }
    EXPECT_EQ(sameCenters, 0u);
    EXPECT_EQ(sameRadii, 0u);
}

// Pins the whole chain for radii that need no libm: std::mt19937_64 (standardised), the SplitMix64
// seeding, the 53-bit conversion and the placement arithmetic. If this fails after a deliberate change
// of the sampler, clouds of existing scene files change too: say so in the change.
TEST(DropletCloud, FixedRadiusCloudIsPinnedBitForBit) {
    const Scene scene =
        parseScene(sceneWith("", cloud(R"("count": 3)", R"({"distribution": "fixed", "value": 0.1})")), "scene.json");
    ASSERT_EQ(scene.shapes.size(), 3u);
    const std::vector<Point> expected{{0x1.23217710ddffp-1, 0x1.0f58ea17c9babp-1, 0x1.7326950b5c666p-2},
                                      {0x1.bccd9ab3e2052p-1, 0x1.dfd9d8c0b784p-3, 0x1.6642de6fc2d75p-1},
                                      {0x1.9d404bde09108p-2, 0x1.5dcc2bce5c7fp-1, 0x1.3b22699b38a2ap-3}};
    for (std::size_t id = 0; id < 3; ++id) {
        EXPECT_EQ(sphereAt(scene, id).radius(), 0.1);
        EXPECT_EQ(sphereAt(scene, id).center(), expected[id])
            << "droplet " << id << ": " << sphereAt(scene, id).center().transpose();
    }
}

TEST(DropletCloud, CountIsHonouredAndIdsFollowTheExplicitShapes) {
    const std::string shapes =
        R"({"type": "sphere", "name": "big", "center": [5, 5, 5], "radius": 1, "medium": "water"},
           {"type": "box", "min": [-3, -3, -3], "max": [-2, -2, -2], "medium": "air"})";
    const std::string generators = cloud(R"("count": 300)", kLognormal) + ", " +
                                   cloud(R"("count": 200)", R"({"distribution": "fixed", "value": 0.02})", 3,
                                         R"({"min": [2, 0, 0], "max": [3, 1, 1]})");
    const Scene scene = parseScene(sceneWith(shapes, generators), "scene.json");
    ASSERT_EQ(scene.shapes.size(), 502u);
    ASSERT_EQ(scene.shapeNames.size(), 502u);
    EXPECT_EQ(scene.explicitShapeCount, 2u);
    EXPECT_EQ(scene.shapeNames[0], "big");
    EXPECT_EQ(scene.shapes[1]->kind(), ShapeKind::Box);
    for (std::size_t id = 2; id < scene.shapes.size(); ++id) {
        ASSERT_EQ(scene.shapes[id]->kind(), ShapeKind::Sphere);
        EXPECT_EQ(scene.shapeNames[id], "");
        EXPECT_EQ(scene.mediumOf(*scene.shapes[id]).name, "water");
        // Generator order first: the second cloud (x in [2, 3]) comes after all of the first.
        EXPECT_EQ(sphereAt(scene, id).center().x() > 2.0, id >= 302) << "shape " << id;
    }
    // Within a generator, generation order is largest first.
    for (std::size_t id = 3; id < 302; ++id) EXPECT_GE(sphereAt(scene, id - 1).radius(), sphereAt(scene, id).radius());
}

TEST(DropletCloud, ZeroCountMakesNoDroplets) {
    const Scene scene = parseScene(sceneWith("", cloud(R"("count": 0)", kLognormal)), "scene.json");
    EXPECT_TRUE(scene.shapes.empty());
}

TEST(DropletCloud, EveryDropletLiesInsideTheRegion) {
    const Scene scene =
        parseScene(sceneWith("", cloud(R"("count": 2000)", R"({"distribution": "uniform", "min": 0.01, "max": 0.04})",
                                       11, R"({"min": [-1, 2, 0.5], "max": [0.5, 2.8, 1.7]})")),
                   "scene.json");
    const Point lower(-1, 2, 0.5);
    const Point upper(0.5, 2.8, 1.7);
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const Sphere& s = sphereAt(scene, id);
        for (int axis = 0; axis < 3; ++axis) {
            ASSERT_GE(s.center()[axis], lower[axis] + s.radius()) << "droplet " << id << " axis " << axis;
            ASSERT_LE(s.center()[axis], upper[axis] - s.radius()) << "droplet " << id << " axis " << axis;
        }
    }
}

// The exact check, through the octree's own overlap query (Shape::overlaps on every stored shape).
void expectNoOverlaps(const Scene& scene) {
    std::vector<std::unique_ptr<Shape>> copies;
    for (std::size_t id = scene.explicitShapeCount; id < scene.shapes.size(); ++id) {
        copies.push_back(scene.shapes[id]->clone());
    }
    const Octree tree(std::move(copies));
    for (ShapeId id = 0; id < tree.slotCount(); ++id) {
        const std::vector<ShapeId> others = tree.overlapping(*tree.shape(id));
        ASSERT_TRUE(others.empty()) << "droplet " << id << " overlaps droplet " << others.front();
    }
}

TEST(DropletCloud, DropletsNeverOverlapEvenWhenDense) {
    expectNoOverlaps(
        parseScene(sceneWith("", cloud(R"("volume_fraction": 0.25)", R"({"distribution": "fixed", "value": 0.04})")),
                   "scene.json"));
    expectNoOverlaps(parseScene(
        sceneWith("", cloud(R"("count": 20000)", R"({"distribution": "lognormal", "median": 0.005, "sigma": 0.8,)"
                                                 R"( "max": 0.1})")),
        "scene.json"));
}

// Earlier droplets of about this cloud's size sit in its grid; much larger ones are checked one by one.
TEST(DropletCloud, DropletsOfLaterGeneratorsAvoidEarlierOnes) {
    const std::string similar = cloud(R"("volume_fraction": 0.15)", R"({"distribution": "fixed", "value": 0.05})", 1) +
                                ", " + cloud(R"("count": 3000)", kLognormal, 2);
    expectNoOverlaps(parseScene(sceneWith("", similar), "scene.json"));
    const std::string mistAfterDrops = cloud(R"("count": 10)", R"({"distribution": "fixed", "value": 0.15})", 1) +
                                       ", " +
                                       cloud(R"("count": 5000)", R"({"distribution": "fixed", "value": 0.004})", 2);
    const Scene scene = parseScene(sceneWith("", mistAfterDrops), "scene.json");
    ASSERT_EQ(scene.shapes.size(), 5010u);
    expectNoOverlaps(scene);
}

// Droplets keep clear of explicit shapes, except that they may nest inside a box or a sphere
// (the scene's nesting rule); they never contain an explicit shape.
TEST(DropletCloud, DropletsRespectExplicitShapesAndMayNestInBoxesAndSpheres) {
    const std::string shapes =
        R"({"type": "sphere", "center": [0.3, 0.3, 0.3], "radius": 0.2, "medium": "air"},
           {"type": "ellipsoid", "center": [0.7, 0.7, 0.5], "semi_axes": [0.25, 0.1, 0.15],
            "rotation": {"axis": [1, 1, 0], "angle_deg": 40}, "medium": "air"},
           {"type": "box", "min": [0.6, 0.1, 0.1], "max": [0.9, 0.4, 0.3], "medium": "air"},
           {"type": "sphere", "center": [0.5, 0.5, 0.9], "radius": 0.005, "medium": "air"},
           {"type": "box", "min": [-0.5, -0.5, -0.5], "max": [1.5, 1.5, 1.5], "medium": "air"})";
    const Scene scene = parseScene(sceneWith(shapes, cloud(R"("count": 4000)", kLognormal)), "scene.json");
    ASSERT_EQ(scene.shapes.size(), 4005u);
    std::size_t nestedInSphere = 0;
    std::size_t nestedInBox = 0;
    for (std::size_t id = scene.explicitShapeCount; id < scene.shapes.size(); ++id) {
        const Shape& droplet = *scene.shapes[id];
        for (std::size_t other = 0; other < scene.explicitShapeCount; ++other) {
            const Shape& shape = *scene.shapes[other];
            if (!droplet.overlaps(shape)) continue;
            ASSERT_TRUE(nestsInside(droplet, shape)) << "droplet " << id << " overlaps shapes[" << other << "]";
            nestedInSphere += other == 0 ? 1 : 0;
            nestedInBox += other == 2 ? 1 : 0;
        }
    }
    // The big box around the region holds every droplet; the others get their share by volume.
    EXPECT_GT(nestedInSphere, 0u);
    EXPECT_GT(nestedInBox, 0u);
    expectNoOverlaps(scene);
}

// The cloud's volume is the first running total of drawn volumes to reach the target, so it lies in
// [target, target + one droplet's volume) (up to the rounding of the sums: 1e-12 relative).
TEST(DropletCloud, VolumeFractionIsReachedWithinOneDroplet) {
    for (const double target : {0.001, 0.05, 0.3}) {
        const Scene scene =
            parseScene(sceneWith("", cloud(R"("volume_fraction": )" + std::to_string(target),
                                           R"({"distribution": "lognormal", "median": 0.02, "sigma": 0.4})")),
                       "scene.json");
        double volume = 0.0;
        double largest = 0.0;
        for (const auto& shape : scene.shapes) {
            volume += shape->volume();
            largest = std::max(largest, shape->volume());
        }
        EXPECT_GE(volume, target * (1.0 - 1e-12)) << "target " << target;
        EXPECT_LT(volume - target, largest * (1.0 + 1e-12)) << "target " << target;
    }
}

TEST(DropletCloudErrors, UnknownTypeAndDistribution) {
    EXPECT_EQ(generatorError(R"({"type": "mist"})"),
              "scene.json: generators[0].type: unknown generator type \"mist\" (known: droplet_cloud)");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "gamma", "shape": 2})")),
              "scene.json: generators[0].radius.distribution: unknown distribution \"gamma\" (known: fixed, "
              "uniform, lognormal, rosin_rammler)");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "fixed", "value": 0.1, "min": 0.01})")),
              "scene.json: generators[0].radius: unknown key \"min\" (valid keys: distribution, value)");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "generators": {}})"),
              "scene.json: generators: expected an array, got object");
}

TEST(DropletCloudErrors, CountAndVolumeFraction) {
    const std::string radius = R"({"distribution": "fixed", "value": 0.01})";
    EXPECT_EQ(generatorError(cloud(R"("count": 10, "volume_fraction": 0.1)", radius)),
              "scene.json: generators[0]: give either \"count\" or \"volume_fraction\", not both");
    EXPECT_EQ(generatorError(R"({"type": "droplet_cloud", "region": {"min": [0, 0, 0], "max": [1, 1, 1]},
                                 "radius": {"distribution": "fixed", "value": 0.01}, "medium": "water"})"),
              "scene.json: generators[0]: missing required key \"count\" or \"volume_fraction\"");
    EXPECT_EQ(generatorError(cloud(R"("count": -1)", radius)), "scene.json: generators[0].count: must be >= 0");
    EXPECT_EQ(generatorError(cloud(R"("count": 1e3)", radius)),
              "scene.json: generators[0].count: must be an integer, got 1000.0");
    EXPECT_EQ(generatorError(cloud(R"("count": 10000001)", radius)),
              "scene.json: generators[0].count: must be <= 10000000 (a scene generates at most 10000000 "
              "droplets; 0 already generated)");
    EXPECT_EQ(generatorError(cloud(R"("volume_fraction": 0)", radius)),
              "scene.json: generators[0].volume_fraction: must be > 0");
    EXPECT_EQ(generatorError(cloud(R"("volume_fraction": 0.31)", radius)),
              "scene.json: generators[0].volume_fraction: must be <= 0.3 (denser random packings jam; see "
              "docs/scene-format.md)");
    EXPECT_EQ(generatorError(cloud(R"("volume_fraction": 0.01)", R"({"distribution": "fixed", "value": 1e-5})")),
              "scene.json: generators[0].volume_fraction: needs more than 10000000 droplets of this size (a "
              "scene generates at most 10000000); use larger radii or a smaller region");
}

TEST(DropletCloudErrors, BadDistributionParameters) {
    EXPECT_EQ(
        generatorError(cloud(R"("count": 10)", R"({"distribution": "lognormal", "median": 0.01, "sigma": -0.3})")),
        "scene.json: generators[0].radius.sigma: must be >= 0");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "uniform", "min": 0.02, "max": 0.01})")),
              "scene.json: generators[0].radius.max: must be > \"min\"");
    EXPECT_EQ(
        generatorError(cloud(R"("count": 10)", R"({"distribution": "rosin_rammler", "scale": 0.01, "shape": 0})")),
        "scene.json: generators[0].radius.shape: must be > 0");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)",
                                   R"({"distribution": "lognormal", "median": 0.01, "sigma": 0.1, "min": 0.1})")),
              "scene.json: generators[0].radius: [\"min\", \"max\"] keeps less than 1e-06 of the distribution; "
              "check the units of the bounds and of the parameters");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)",
                                   R"({"distribution": "lognormal", "median": 0.01, "sigma": 0, "max": 0.005})")),
              "scene.json: generators[0].radius: [\"min\", \"max\"] excludes the median 0.01, the only radius when "
              "\"sigma\" is 0");
}

TEST(DropletCloudErrors, RegionAndRadiiThatDoNotFit) {
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", kLognormal, 7, R"({"min": [0, 1, 0], "max": [1, 1, 1]})")),
              "scene.json: generators[0].region.max: must be > \"min\" on every axis (y: max 1 <= min 1)");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "fixed", "value": 0.6})")),
              "scene.json: generators[0].radius: a droplet of radius 0.6 does not fit in the region (its smallest "
              "side is 1)");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "lognormal", "median": 0.3, "sigma": 1})")),
              "scene.json: generators[0].radius: a droplet of radius 1.5 does not fit in the region (its smallest "
              "side is 1); bound the radii with \"max\"");
    EXPECT_EQ(generatorError(cloud(R"("count": 10)", R"({"distribution": "fixed", "value": 1e-10})")),
              "scene.json: generators[0].radius: a droplet of radius 1e-10 is too small for the region (radii must "
              "be >= 1e-09 of its largest side or coordinate); bound the radii with \"min\"");
}

// A droplet of radius 0.4 leaves centres only in [0.4, 0.6]^3, too close together for a second one.
TEST(DropletCloudErrors, RegionTooFullSaysHowFarItGot) {
    EXPECT_EQ(generatorError(cloud(R"("count": 2)", R"({"distribution": "fixed", "value": 0.4})")),
              "scene.json: generators[0]: placed 1 of 2 droplets before the region filled (volume fraction "
              "reached 0.27); lower count or volume_fraction");
}

TEST(DropletCloudErrors, MediumAndKeys) {
    EXPECT_EQ(generatorError(R"({"type": "droplet_cloud", "region": {"min": [0, 0, 0], "max": [1, 1, 1]},
                                 "count": 1, "radius": {"distribution": "fixed", "value": 0.1}, "medium": "ink"})"),
              "scene.json: generators[0].medium: unknown medium \"ink\" (defined: air, water)");
    EXPECT_EQ(generatorError(R"({"type": "droplet_cloud", "region": {"min": [0, 0, 0], "max": [1, 1, 1]},
                                 "count": 1, "radius": {"distribution": "fixed", "value": 0.1}, "medium": "water",
                                 "sed": 3})"),
              "scene.json: generators[0]: unknown key \"sed\" (did you mean \"seed\"?)");
    EXPECT_EQ(generatorError(cloud(R"("count": 1)", R"({"distribution": "fixed", "value": 0.1})", -2)),
              "scene.json: generators[0].seed: must be >= 0");
}

}  // namespace
}  // namespace dropscope
