#pragma once

#include "transport/Event.hpp"

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
// Viridis on a log scale of `weight`: 10^-decades (and below) at the bottom of the map, 1 at the top; for
// ray-tree branches, whose weights span many decades.
Colour logWeightColour(double weight, double decades = 6.0);
// The colour of an event type (markers, paths coloured by event): a small fixed palette.
Colour eventColour(EventType type);

}  // namespace dropscope::render
