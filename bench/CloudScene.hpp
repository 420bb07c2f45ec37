#pragma once

#include <cstddef>
#include <string>

namespace dropscope::bench {

// The benchmarks' droplet cloud (trace_bench, render_bench), as scene text for parseScene: `droplets`
// water droplets (n 1.3337, kappa 1.9e-9 at 532 nm) in air, with the radii of assets/scenes/cloud.json
// (lognormal, median 0.1 mm, sigma 0.35, at most 0.5 mm), generator seed 7, in the cube of half-side
// `halfSide` mm about the origin; octree depth 10, 16 shapes per leaf. One beam along +z from two
// half-sides below the centre fills the disk inscribed in the cube's face, so every photon enters the
// cloud. With 1e5 droplets and half-side 15 mm the droplets take 2.7 % of the volume and the mean
// optical depth along the beam is about 4.5.
inline std::string cloudSceneText(std::size_t droplets, double halfSide) {
    const std::string h = std::to_string(halfSide);
    return R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
  "media": {"air": {"n": 1.000278}, "water": {"n": 1.3337, "kappa": 1.9e-9}},
  "generators": [{"type": "droplet_cloud", "region": {"min": [-)" +
           h + ", -" + h + ", -" + h + R"(], "max": [)" + h + ", " + h + ", " + h + R"(]}, "count": )" +
           std::to_string(droplets) + R"(,
    "radius": {"distribution": "lognormal", "median": 0.1, "sigma": 0.35, "max": 0.5}, "medium": "water", "seed": 7}],
  "sources": [{"type": "beam", "origin": [0, 0, -)" +
           std::to_string(2.0 * halfSide) + R"(], "direction": [0, 0, 1], "radius": )" + h + R"(}],
  "octree": {"max_depth": 10, "max_shapes_per_leaf": 16}})";
}

}  // namespace dropscope::bench
