#pragma once

#include "render/Chords.hpp"
#include "render/DrawData.hpp"
#include "transport/RayTree.hpp"

#include <cstdint>
#include <vector>

namespace dropscope::render {

// Which of a ray tree's segments (addRayTree's) are chords, and the order they are drawn in: heaviest first, equal
// weights in the tree's order, so that where branches coincide (a head-on reflection retraces its ray) the heavier,
// drawn first, wins the depth test. For a large tree this is most of addRayTree's time (docs/performance.md, "The
// app"), so the app works it out where it traces the tree, on a worker for a large scene.
struct RayTreeDrawOrder {
    std::vector<std::uint32_t> order;  // segment indices
    std::vector<bool> chord;           // by segment index
};

// `octree` and `slotOfShape` as isChord's; without an octree no segment is a chord.
RayTreeDrawOrder rayTreeDrawOrder(const RayTree& tree, const Octree* octree,
                                  const std::vector<ShapeId>* slotOfShape = nullptr);

// The branches of a ray tree: each segment from an event to the next one along its branch, coloured by
// the weight the branch leaves the first event with, on viridis with a log scale (logWeightColour: the
// weights span 1 to the tree's minimum weight, 1e-6 by default). An escaping branch goes on for
// `escapeLength`. With `chords`, the segments that are chords of a sphere or ellipsoid (isChord) go to its
// batch instead, in the same order. `prepared`, this tree's rayTreeDrawOrder against shapes the same as
// `chords`'s octree holds, is taken instead of working it out again (its chords only with `chords`); one with
// another count of segments than the tree's is not taken.
void addRayTree(LineBatch& lines, const RayTree& tree, double escapeLength, const ChordSplit* chords = nullptr,
                const RayTreeDrawOrder* prepared = nullptr);

}  // namespace dropscope::render
