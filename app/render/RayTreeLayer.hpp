#pragma once

#include "render/Chords.hpp"
#include "render/DrawData.hpp"
#include "transport/RayTree.hpp"

namespace dropscope::render {

// The branches of a ray tree: each segment from an event to the next one along its branch, coloured by
// the weight the branch leaves the first event with, on viridis with a log scale (logWeightColour: the
// weights span 1 to the tree's minimum weight, 1e-6 by default). An escaping branch goes on for
// `escapeLength`. With `chords`, the segments that are chords of a sphere or ellipsoid (isChord) go to its
// batch instead, in the same order.
void addRayTree(LineBatch& lines, const RayTree& tree, double escapeLength, const ChordSplit* chords = nullptr);

}  // namespace dropscope::render
