#include "render/RayTreeLayer.hpp"

#include "render/Colour.hpp"

#include <algorithm>

namespace dropscope::render {

namespace {

struct Segment {
    Point from;
    Point to;
    double weight;
    bool chord;
};

}  // namespace

void addRayTree(LineBatch& lines, const RayTree& tree, double escapeLength, const ChordSplit* chords) {
    std::vector<Segment> segments;
    for (const RayTreeNode& node : tree.nodes) {
        if (node.parent < 0) continue;
        const Event& from = tree.nodes[static_cast<std::size_t>(node.parent)].event;
        const Event& to = node.event;
        if (to.position != from.position) {
            segments.push_back({from.position, to.position, from.weight,
                                chords && isChord(from, to, chords->octree, chords->slotOfShape)});
        }
        // A leaf sits where its branch last was: an escape goes on along its direction, the other leaves
        // (truncated, lost, absorbed with no surface ahead) end there.
        if (to.type == EventType::Escape) {
            segments.push_back({to.position, to.position + escapeLength * to.direction.vector(), to.weight, false});
        }
    }
    // Heaviest first: where branches coincide (a head-on reflection retraces its ray) the first one
    // drawn wins the depth test, so the picture shows the heavier.
    std::stable_sort(segments.begin(), segments.end(),
                     [](const Segment& a, const Segment& b) { return a.weight > b.weight; });
    for (const Segment& segment : segments) {
        (segment.chord ? chords->batch : lines).add(segment.from, segment.to, logWeightColour(segment.weight));
    }
}

}  // namespace dropscope::render
