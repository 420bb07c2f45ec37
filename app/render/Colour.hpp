#pragma once

#include <array>
#include <cstddef>

namespace dropscope::render {

using Colour = std::array<float, 4>;  // linear RGBA in [0, 1]

// The colour of medium `index` (a fixed palette, repeating): water-like media blue, glass green, ...
Colour mediumColour(std::size_t index);
// The colour of octree level `level` (0 = root).
Colour levelColour(int level);
// Viridis (the perceptual colour map of matplotlib) at t in [0, 1]; t outside is clamped.
Colour viridis(double t);

}  // namespace dropscope::render
