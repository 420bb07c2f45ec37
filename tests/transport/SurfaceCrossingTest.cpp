#include "TransportFixtures.hpp"

#include "geometry/Sphere.hpp"
#include "optics/Fresnel.hpp"
#include "scene/SceneOverlaps.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <optional>

namespace dropscope {
namespace {

using testing::sceneFromJson;

// A glass cell (id 0) holding a water drop (1) holding an air bubble (2), and a free drop (3) outside.
Scene nestedScene() {
    return sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5}, "water": {"n": 1.3337})",
                         R"({"type": "box", "min": [-3, -3, -3], "max": [3, 3, 3], "medium": "glass"},
                            {"type": "sphere", "center": [0, 0, 0], "radius": 2, "medium": "water"},
                            {"type": "sphere", "center": [0, 0, 1], "radius": 0.5, "medium": "air"},
                            {"type": "sphere", "center": [10, 0, 0], "radius": 1, "medium": "water"})",
                         "");
}

TEST(OpticalScene, EachShapesParentIsTheSmallestShapeItNestsIn) {
    const OpticalScene scene(nestedScene());
    EXPECT_EQ(scene.parentOf(0), OpticalScene::kAmbient);
    EXPECT_EQ(scene.parentOf(1), 0U);
    EXPECT_EQ(scene.parentOf(2), 1U);
    EXPECT_EQ(scene.parentOf(3), OpticalScene::kAmbient);
}

TEST(OpticalScene, ACloudGeneratedInsideAGlassCellHasTheCellAsParent) {
    const Scene scene = parseScene(
        R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "glass": {"n": 1.5}, "water": {"n": 1.33}},
            "shapes": [{"type": "box", "min": [0, 0, 0], "max": [10, 10, 10], "medium": "glass"},
                       {"type": "sphere", "center": [20, 5, 5], "radius": 1, "medium": "water"}],
            "generators": [{"type": "droplet_cloud", "region": {"min": [1, 1, 1], "max": [9, 9, 9]}, "count": 2000,
                            "radius": {"distribution": "fixed", "value": 0.1}, "medium": "water", "seed": 3},
                           {"type": "droplet_cloud", "region": {"min": [15, 0, 0], "max": [25, 10, 10]}, "count": 500,
                            "radius": {"distribution": "fixed", "value": 0.1}, "medium": "water", "seed": 4}]})",
        "cloud-in-cell.json");
    const OpticalScene optical(scene);
    ASSERT_EQ(optical.octree().slotCount(), 2502U);
    EXPECT_EQ(optical.parentOf(0), OpticalScene::kAmbient);
    EXPECT_EQ(optical.parentOf(1), OpticalScene::kAmbient);
    for (ShapeId id = 2; id < 2002; ++id) ASSERT_EQ(optical.parentOf(id), 0U) << id;
    // The second cloud surrounds the free sphere; droplets placed wholly inside it nest in it.
    int nestedInSphere = 0;
    for (ShapeId id = 2002; id < 2502; ++id) {
        const auto& droplet = static_cast<const Sphere&>(*optical.octree().shape(id));
        const bool inside = (droplet.center() - Point(20, 5, 5)).norm() + droplet.radius() <= 1.0;
        nestedInSphere += inside;
        ASSERT_EQ(optical.parentOf(id), inside ? 1U : OpticalScene::kAmbient) << id;
    }
    EXPECT_GT(nestedInSphere, 0);
}

// The parents are found a leaf at a time (OpticalScene::findContainers); here against a walk of each shape's own
// path (ties of volume to the first on it) and against every pair of shapes, in a scene of many small leaves:
// clouds in two glass cells, in the water sphere inside each, in an air bubble inside one of those, and in
// two coincident oil spheres (equal volumes: which one holds a droplet is the tie's rule).
TEST(OpticalScene, EachParentIsTheSmallestContainerAmongAllShapes) {
    const Scene scene = parseScene(
        R"({"dropscope": 1, "ambient": "air",
            "media": {"air": {"n": 1}, "glass": {"n": 1.5}, "water": {"n": 1.33}, "oil": {"n": 1.47}},
            "octree": {"max_shapes_per_leaf": 4},
            "shapes": [{"type": "box", "min": [0, 0, 0], "max": [10, 10, 10], "medium": "glass"},
                       {"type": "sphere", "center": [5, 5, 5], "radius": 3, "medium": "water"},
                       {"type": "sphere", "center": [5, 5, 6], "radius": 1.2, "medium": "air"},
                       {"type": "box", "min": [20, 0, 0], "max": [30, 10, 10], "medium": "glass"},
                       {"type": "sphere", "center": [25, 5, 5], "radius": 2, "medium": "water"},
                       {"type": "sphere", "center": [40, 5, 5], "radius": 2, "medium": "oil"},
                       {"type": "sphere", "center": [40, 5, 5], "radius": 2, "medium": "oil"}],
            "generators": [{"type": "droplet_cloud", "region": {"min": [0.5, 0.5, 0.5], "max": [9.5, 9.5, 9.5]},
                            "count": 1500, "radius": {"distribution": "uniform", "min": 0.05, "max": 0.2},
                            "medium": "oil", "seed": 7},
                           {"type": "droplet_cloud", "region": {"min": [19, -1, -1], "max": [31, 11, 11]},
                            "count": 1500, "radius": {"distribution": "uniform", "min": 0.05, "max": 0.2},
                            "medium": "water", "seed": 8},
                           {"type": "droplet_cloud", "region": {"min": [38.5, 3.5, 3.5], "max": [41.5, 6.5, 6.5]},
                            "count": 200, "radius": {"distribution": "uniform", "min": 0.05, "max": 0.1},
                            "medium": "water", "seed": 9}]})",
        "clouds-in-cells.json");
    const OpticalScene optical(scene);
    const Octree& octree = optical.octree();
    ASSERT_EQ(octree.slotCount(), 3207U);
    std::map<ShapeId, int> children;
    for (ShapeId inner = 0; inner < octree.slotCount(); ++inner) {
        const Shape& shape = *octree.shape(inner);
        ShapeId walked = OpticalScene::kAmbient;  // what a walk of its own path finds
        octree.forEachShapeAlongPath(shape.bounds().center(), [&](ShapeId outer) {
            const Shape& other = *octree.shape(outer);
            if (outer == inner || other.volume() <= shape.volume() || !nestsInside(shape, other)) return;
            if (walked == OpticalScene::kAmbient || other.volume() < octree.shape(walked)->volume()) walked = outer;
        });
        ASSERT_EQ(optical.parentOf(inner), walked) << "shape " << inner;
        std::optional<double> smallest;  // the smallest volume of all that hold it
        for (ShapeId outer = 0; outer < octree.slotCount(); ++outer) {
            const Shape& other = *octree.shape(outer);
            if (outer == inner || other.volume() <= shape.volume() || !nestsInside(shape, other)) continue;
            if (!smallest || other.volume() < *smallest) smallest = other.volume();
        }
        ASSERT_EQ(walked == OpticalScene::kAmbient, !smallest) << "shape " << inner;
        if (smallest) {
            ASSERT_EQ(octree.shape(walked)->volume(), *smallest) << "shape " << inner;
        }
        ++children[walked];
    }
    // Every container holds droplets (the bubble about a dozen; each droplet between the coincident spheres goes to
    // the first of them on its path, and neither is the other's parent: neither is larger), and some droplets
    // are out in the air.
    for (const ShapeId container : {ShapeId{0}, ShapeId{1}, ShapeId{2}, ShapeId{3}, ShapeId{4}})
        EXPECT_GE(children[container], 5) << "shape " << container;
    EXPECT_GE(children[5] + children[6], 150);
    EXPECT_GE(children[OpticalScene::kAmbient], 100);
}

TEST(OpticalScene, RegionAtIsTheInnermostShapeAroundAPoint) {
    const OpticalScene scene(nestedScene());
    EXPECT_EQ(scene.regionAt(Point(0, 0, 1)), 2U);
    EXPECT_EQ(scene.regionAt(Point(0, 0, -1)), 1U);
    EXPECT_EQ(scene.regionAt(Point(2.5, 2.5, 0)), 0U);
    EXPECT_EQ(scene.regionAt(Point(10, 0, 0)), 3U);
    EXPECT_EQ(scene.regionAt(Point(6, 0, 0)), OpticalScene::kAmbient);
    EXPECT_EQ(scene.mediumOf(OpticalScene::kAmbient).name, "air");
    EXPECT_EQ(scene.mediumOf(2).name, "air");
    EXPECT_EQ(scene.mediumOf(0).name, "glass");
}

TEST(SurfaceCrossing, NamesTheMediaOnBothSidesWhenEnteringAndLeavingNestedShapes) {
    const OpticalScene scene(nestedScene());
    const Direction down(0, 0, -1);
    const MediumId air = 0, glass = 1, water = 2;
    struct Case {
        ShapeId region, shape;
        Point point;
        MediumId from, to;
        ShapeId beyond;
    };
    const Case cases[] = {
        {OpticalScene::kAmbient, 0, Point(0, 0, 3), air, glass, 0},   // into the cell
        {0, 1, Point(0, 0, 2), glass, water, 1},                      // into the drop
        {1, 2, Point(0, 0, 1.5), water, air, 2},                      // into the bubble
        {2, 2, Point(0, 0, 0.5), air, water, 1},                      // out of the bubble
        {1, 1, Point(0, 0, -2), water, glass, 0},                     // out of the drop
        {0, 0, Point(0, 0, -3), glass, air, OpticalScene::kAmbient},  // out of the cell
    };
    for (const Case& c : cases) {
        const SurfaceCrossing crossing = crossSurface(scene, c.region, c.shape, c.point, down, FresnelModel::Exact);
        ASSERT_EQ(crossing.kind, SurfaceCrossing::Kind::Interface) << c.point.transpose();
        EXPECT_EQ(crossing.from, c.from);
        EXPECT_EQ(crossing.to, c.to);
        EXPECT_EQ(crossing.regionBeyond, c.beyond);
        const double n1 = scene.media()[c.from].n, n2 = scene.media()[c.to].n;
        EXPECT_DOUBLE_EQ(crossing.reflectance, fresnelReflectance(1.0, n1, n2).unpolarised());
        EXPECT_EQ(crossing.transmitted.vector(), down.vector());  // normal incidence goes straight on
        EXPECT_EQ(crossing.reflected().vector(), Eigen::Vector3d(0, 0, 1));
    }
}

TEST(SurfaceCrossing, ACrossingThatDoesNotBoundTheCurrentRegionIsLost) {
    const OpticalScene scene(nestedScene());
    // Leaving the free drop while supposedly in the ambient air: rounding (or touching shapes) put the
    // photon on the wrong side; the tracer must not guess a medium.
    const SurfaceCrossing crossing =
        crossSurface(scene, OpticalScene::kAmbient, 3, Point(11, 0, 0), Direction(1, 0, 0), FresnelModel::Exact);
    EXPECT_EQ(crossing.kind, SurfaceCrossing::Kind::Lost);
    EXPECT_EQ(crossing.lostReason, LostReason::MediumMismatch);
}

TEST(SurfaceCrossing, ABoxEdgeHasNoNormalAndIsLost) {
    const OpticalScene scene(nestedScene());
    const SurfaceCrossing crossing =
        crossSurface(scene, OpticalScene::kAmbient, 0, Point(3, 3, 0), Direction(-1, 0, 0), FresnelModel::Exact);
    EXPECT_EQ(crossing.kind, SurfaceCrossing::Kind::Lost);
    EXPECT_EQ(crossing.lostReason, LostReason::UndefinedNormal);
}

TEST(SurfaceCrossing, ATangentRayNeitherEntersNorReflects) {
    const OpticalScene scene(nestedScene());
    const SurfaceCrossing crossing =
        crossSurface(scene, OpticalScene::kAmbient, 3, Point(10, 0, 1), Direction(1, 0, 0), FresnelModel::Exact);
    EXPECT_EQ(crossing.kind, SurfaceCrossing::Kind::Tangent);
}

TEST(SurfaceCrossing, PastTheCriticalAngleTheRayIsTotallyReflected) {
    const OpticalScene scene(nestedScene());
    // Inside the glass towards the top face at 60 degrees from the normal; sin(60) * 1.5 > 1.
    const Direction up(std::sin(M_PI / 3), 0, std::cos(M_PI / 3));
    const SurfaceCrossing crossing = crossSurface(scene, 0, 0, Point(2.5, 2.5, 3), up, FresnelModel::Exact);
    ASSERT_EQ(crossing.kind, SurfaceCrossing::Kind::Interface);
    EXPECT_TRUE(crossing.totalInternalReflection);
    EXPECT_EQ(crossing.reflectance, 1.0);
    EXPECT_FALSE(crossing.transmitted);
    EXPECT_NEAR((crossing.reflected().vector() - Eigen::Vector3d(up.x(), 0, -up.z())).norm(), 0.0,
                4 * std::numeric_limits<double>::epsilon());  // V - 2(V.N)N: a few roundings of unit terms
}

TEST(SurfaceCrossing, SchlickIsUsedOnlyWhenAsked) {
    const OpticalScene scene(nestedScene());
    const Direction oblique(std::sin(1.0), 0, -std::cos(1.0));
    const Point top(0, 0, 3);
    const double exact = crossSurface(scene, OpticalScene::kAmbient, 0, top, oblique, FresnelModel::Exact).reflectance;
    const double schlick =
        crossSurface(scene, OpticalScene::kAmbient, 0, top, oblique, FresnelModel::Schlick).reflectance;
    EXPECT_DOUBLE_EQ(exact, fresnelReflectance(std::cos(1.0), 1.0, 1.5).unpolarised());
    EXPECT_DOUBLE_EQ(schlick, schlickReflectance(std::cos(1.0), 1.0, 1.5));
    EXPECT_GT(std::abs(exact - schlick), 1e-3);
}

}  // namespace
}  // namespace dropscope
