#pragma once

// Scenes several UI test files open.
namespace dropscope::gui::testing {

// A water sphere on the axis of a ray source: the first interface is at (0, 0, -1), head on.
inline constexpr const char* kAxisScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1]}],
  "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
})";

// A cloud of 300 droplets: enough for an octree of several levels.
inline constexpr const char* kCloudScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "octree": {"max_shapes_per_leaf": 4},
  "generators": [{"type": "droplet_cloud", "region": {"min": [-2, -2, -2], "max": [2, 2, 2]}, "count": 300,
                  "radius": {"distribution": "fixed", "value": 0.05}, "medium": "water", "seed": 3}],
  "view": {"eye": [6, 4, 7], "target": [0, 0, 0]}
})";

}  // namespace dropscope::gui::testing
