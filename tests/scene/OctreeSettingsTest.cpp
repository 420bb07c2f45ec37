// Scene key "octree": {"max_depth": 0..30, "max_shapes_per_leaf": >= 1}, both optional.
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using test::sceneErrorOf;

TEST(OctreeSettings, AreReadWithDefaults) {
    const Scene defaults = parseScene(R"({"dropscope": 1})", "scene.json");
    EXPECT_EQ(defaults.octree.maxDepth, OctreeSettings{}.maxDepth);
    EXPECT_EQ(defaults.octree.maxShapesPerLeaf, OctreeSettings{}.maxShapesPerLeaf);
    const Scene depthOnly = parseScene(R"({"dropscope": 1, "octree": {"max_depth": 0}})", "scene.json");
    EXPECT_EQ(depthOnly.octree.maxDepth, 0);
    EXPECT_EQ(depthOnly.octree.maxShapesPerLeaf, OctreeSettings{}.maxShapesPerLeaf);
    const Scene both =
        parseScene(R"({"dropscope": 1, "octree": {"max_depth": 30, "max_shapes_per_leaf": 1}})", "scene.json");
    EXPECT_EQ(both.octree.maxDepth, 30);
    EXPECT_EQ(both.octree.maxShapesPerLeaf, 1);
}

TEST(OctreeSettings, OutOfRangeOrUnknownKeysAreErrors) {
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": {"max_depth": 31}})"),
              "scene.json: octree.max_depth: must be in 0..30, got 31");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": {"max_depth": -1}})"),
              "scene.json: octree.max_depth: must be in 0..30, got -1");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": {"max_depth": 2.5}})"),
              "scene.json: octree.max_depth: must be an integer, got 2.5");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": {"max_shapes_per_leaf": 0}})"),
              "scene.json: octree.max_shapes_per_leaf: must be >= 1, got 0");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": {"max_dept": 3}})"),
              "scene.json: octree: unknown key \"max_dept\" (did you mean \"max_depth\"?)");
    EXPECT_EQ(sceneErrorOf(R"({"dropscope": 1, "octree": 3})"), "scene.json: octree: expected an object, got number");
}

}  // namespace
}  // namespace dropscope
