// The issue's promise: the same pixels for the same arguments on every run.
#include "scene/SceneLoader.hpp"
#include "snapshot/Snapshot.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace dropscope {
namespace {

TEST(Snapshot, SameArgumentsGiveIdenticalPixels) {
    // Shapes of every kind, octree cells and traced paths (random, from the seed).
    const Scene scene = parseScene(R"({
      "dropscope": 1, "ambient": "air",
      "media": {"air": {"n": 1}, "water": {"n": 1.333}, "glass": {"n": 1.5}},
      "shapes": [
        {"type": "box", "min": [-2, -1, -1], "max": [2, 1, 1], "medium": "glass"},
        {"type": "sphere", "center": [-1, 0, 0], "radius": 0.5, "medium": "water"},
        {"type": "ellipsoid", "center": [1, 0, 0], "semi_axes": [0.6, 0.4, 0.3],
         "rotation": {"axis": [1, 1, 0], "angle_deg": 30}, "medium": "water"}
      ],
      "sources": [{"type": "beam", "origin": [0, 0, -4], "direction": [0, 0, 1], "radius": 1.5}]
    })",
                                   "determinism.json");
    snapshot::SnapshotOptions options;
    options.width = 96;
    options.height = 64;
    options.octreeLevel = 1;
    options.paths = 20;
    options.photons = 200;
    options.seed = 11;
    const snapshot::Image first = snapshot::renderSnapshot(scene, options);
    const snapshot::Image second = snapshot::renderSnapshot(scene, options);
    ASSERT_EQ(first.rgba.size(), 4u * 96u * 64u);
    EXPECT_TRUE(first.rgba == second.rgba) << "two renders of the same snapshot differ";
    // Not trivially equal: a good part of the image is drawn.
    int drawn = 0;
    for (int y = 0; y < first.height; ++y) {
        for (int x = 0; x < first.width; ++x) {
            drawn += std::equal(first.pixel(x, y), first.pixel(x, y) + 3, first.pixel(0, 0)) ? 0 : 1;
        }
    }
    EXPECT_GT(drawn, first.width * first.height / 4);
}

}  // namespace
}  // namespace dropscope
