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

struct Segment {
    Point from;
    Point to;
    double weight;
    bool chord;
};

// The segments' indices heaviest first, equal weights in their order: a stable radix sort, a byte a pass
// from the lowest, of the weights' bits, which for weights > 0 order as the weights do (a weight of 0 or
// less, or NaN, which a tree does not hold, sorts as 0, last). For a tree through 1e6 droplets this took about
// two thirds of std::sort's time on (weight, index) pairs (docs/performance.md, "The app").
std::vector<std::uint32_t> heaviestFirst(const std::vector<Segment>& segments) {
    struct Keyed {
        std::uint64_t key;  // descending weight as ascending key
        std::uint32_t index;
    };
    constexpr int kBytes = 8;
    const std::size_t n = segments.size();
    assert(n <= std::numeric_limits<std::uint32_t>::max());  // a tree's parents are int32
    std::vector<Keyed> keyed(n);
    // Per byte of the key, each value's count at value + 1, made in one read of the keys.
    std::array<std::array<std::size_t, 257>, kBytes> counts{};
    for (std::size_t k = 0; k < n; ++k) {
        const double weight = segments[k].weight;
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

void addRayTree(LineBatch& lines, const RayTree& tree, double escapeLength, const ChordSplit* chords) {
    std::vector<Segment> segments;
    segments.reserve(tree.nodes.size());
    std::size_t chordCount = 0;
    for (const RayTreeNode& node : tree.nodes) {
        if (node.parent < 0) continue;
        const Event& from = tree.nodes[static_cast<std::size_t>(node.parent)].event;
        const Event& to = node.event;
        if (to.position != from.position) {
            const bool chord = chords && isChord(from, to, chords->octree, chords->slotOfShape);
            segments.push_back({from.position, to.position, from.weight, chord});
            chordCount += chord ? 1 : 0;
        }
        // A leaf sits where its branch last was: an escape goes on along its direction, the other leaves
        // (truncated, lost, absorbed with no surface ahead) end there.
        if (to.type == EventType::Escape) {
            segments.push_back({to.position, to.position + escapeLength * to.direction.vector(), to.weight, false});
        }
    }
    // Heaviest first: where branches coincide (a head-on reflection retraces its ray) the first one
    // drawn wins the depth test, so the picture shows the heavier. Equal weights keep the tree's order.
    const std::vector<std::uint32_t> order = heaviestFirst(segments);
    lines.reserveMore(segments.size() - chordCount);
    if (chords) chords->batch.reserveMore(chordCount);
    // The segments are read out of order: each one fetched a few ahead of its turn, both of the cache lines
    // it may straddle.
    constexpr std::size_t kPrefetchAhead = 16;
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (k + kPrefetchAhead < order.size()) {
            const auto* ahead = reinterpret_cast<const char*>(&segments[order[k + kPrefetchAhead]]);
            __builtin_prefetch(ahead);
            __builtin_prefetch(ahead + sizeof(Segment) - 1);
        }
        const Segment& segment = segments[order[k]];
        (segment.chord ? chords->batch : lines).add(segment.from, segment.to, logWeightColour(segment.weight));
    }
}

}  // namespace dropscope::render
