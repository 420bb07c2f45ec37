#include "render/RayTreeLayer.hpp"

#include "render/Colour.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstdint>
#include <limits>

namespace dropscope::render {

namespace {

// Calls onSegment(from, to, escape) for each segment of the tree, in the tree's order: from each event to its child
// where the two lie apart, then, after an escape, the escape's own tail (from = to = the escape). A leaf sits
// where its branch last was: an escape goes on along its direction, the other leaves (truncated, lost, absorbed
// with no surface ahead) end there.
template <class OnSegment>
void forEachSegment(const RayTree& tree, OnSegment onSegment) {
    for (const RayTreeNode& node : tree.nodes) {
        if (node.parent < 0) continue;
        const Event& from = tree.nodes[static_cast<std::size_t>(node.parent)].event;
        const Event& to = node.event;
        if (to.position != from.position) onSegment(from, to, false);
        if (to.type == EventType::Escape) onSegment(to, to, true);
    }
}

// The indices of `weights` heaviest first, equal weights in their order: a stable radix sort, a byte a pass
// from the lowest, of the weights' bits, which for weights > 0 order as the weights do (a weight of 0 or
// less, or NaN, which a tree does not hold, sorts as 0, last). For a tree through 1e6 droplets this took about
// two thirds of std::sort's time on (weight, index) pairs (docs/performance.md, "The app").
std::vector<std::uint32_t> heaviestFirst(const std::vector<double>& weights) {
    struct Keyed {
        std::uint64_t key;  // descending weight as ascending key
        std::uint32_t index;
    };
    constexpr int kBytes = 8;
    const std::size_t n = weights.size();
    assert(n <= std::numeric_limits<std::uint32_t>::max());  // a tree's parents are int32
    std::vector<Keyed> keyed(n);
    // Per byte of the key, each value's count at value + 1, made in one read of the keys.
    std::array<std::array<std::size_t, 257>, kBytes> counts{};
    for (std::size_t k = 0; k < n; ++k) {
        const double weight = weights[k];
        const std::uint64_t key = ~(weight > 0.0 ? std::bit_cast<std::uint64_t>(weight) : std::uint64_t{0});
        keyed[k] = {key, static_cast<std::uint32_t>(k)};
        for (int byte = 0; byte < kBytes; ++byte) ++counts[byte][((key >> (8 * byte)) & 0xFF) + 1];
    }
    std::vector<Keyed> spare(n);
    for (int byte = 0; byte < kBytes; ++byte) {
        std::array<std::size_t, 257>& start = counts[byte];
        // Every key with one value of this byte: the pass would move nothing.
        if (std::find(start.begin() + 1, start.end(), n) != start.end()) continue;
        // Now each value's first slot: the count of the smaller values.
        for (std::size_t value = 1; value < start.size(); ++value) start[value] += start[value - 1];
        for (const Keyed& item : keyed) spare[start[(item.key >> (8 * byte)) & 0xFF]++] = item;
        keyed.swap(spare);
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = keyed[k].index;
    return order;
}

}  // namespace

RayTreeDrawOrder rayTreeDrawOrder(const RayTree& tree, const Octree* octree, const std::vector<ShapeId>* slotOfShape) {
    std::vector<double> weights;
    weights.reserve(tree.nodes.size());
    RayTreeDrawOrder drawOrder;
    drawOrder.chord.reserve(tree.nodes.size());
    forEachSegment(tree, [&](const Event& from, const Event& to, bool escape) {
        weights.push_back(from.weight);
        drawOrder.chord.push_back(!escape && octree && isChord(from, to, *octree, slotOfShape));
    });
    drawOrder.order = heaviestFirst(weights);
    return drawOrder;
}

void addRayTree(LineBatch& lines, const RayTree& tree, double escapeLength, const ChordSplit* chords,
                const RayTreeDrawOrder* prepared) {
    struct Segment {
        Point from;
        Point to;
        double weight;
    };
    std::vector<Segment> segments;
    segments.reserve(tree.nodes.size());
    forEachSegment(tree, [&](const Event& from, const Event& to, bool escape) {
        segments.push_back(
            {from.position, escape ? to.position + escapeLength * to.direction.vector() : to.position, from.weight});
    });
    RayTreeDrawOrder workedOut;
    if (!prepared || prepared->order.size() != segments.size()) {
        workedOut = rayTreeDrawOrder(tree, chords ? &chords->octree : nullptr, chords ? chords->slotOfShape : nullptr);
        prepared = &workedOut;
    }
    assert(prepared->chord.size() == prepared->order.size());
    const std::vector<bool>& chord = prepared->chord;
    std::size_t chordCount = 0;
    if (chords) chordCount = static_cast<std::size_t>(std::count(chord.begin(), chord.end(), true));
    lines.reserveMore(segments.size() - chordCount);
    if (chords) chords->batch.reserveMore(chordCount);
    // The segments are read out of order: each one fetched a few ahead of its turn, both of the cache lines
    // it may straddle.
    const std::vector<std::uint32_t>& order = prepared->order;
    constexpr std::size_t kPrefetchAhead = 16;
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (k + kPrefetchAhead < order.size()) {
            const auto* ahead = reinterpret_cast<const char*>(&segments[order[k + kPrefetchAhead]]);
            __builtin_prefetch(ahead);
            __builtin_prefetch(ahead + sizeof(Segment) - 1);
        }
        const std::uint32_t index = order[k];
        const Segment& segment = segments[index];
        (chords && chord[index] ? chords->batch : lines).add(segment.from, segment.to, logWeightColour(segment.weight));
    }
}

}  // namespace dropscope::render
