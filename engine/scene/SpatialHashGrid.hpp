#pragma once

#include "geometry/Vector.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace dropscope {

// A uniform grid of cubic cells over a box (the domain), kept sparse in an open-addressing hash table,
// so only cells that hold something cost memory. For the rejection sampling of droplet clouds: which
// placed items might a candidate touch?
//
// An item is entered in the cells covering its bounds shrunk by up to reach() = cellSize/2 on each
// side (an item no wider than a cell goes into the one cell of its centre); a query scans the cells
// covering its bounds grown by reach(). So every item whose bounds intersect the query's bounds inside
// the domain is visited, while a small item costs one entry and a large one about (width/cell)^3.
//
// Each entry carries a ball given at insertion (a droplet's own sphere), handed to the visitor, so
// that most candidates are rejected from the entry alone, without a second cache miss.
class SpatialHashGrid {
public:
    using Bounds = Eigen::AlignedBox3d;
    struct Ball {
        Point center;
        double radius;
    };
    // Cell coordinates are packed into one 64-bit key, 21 bits per axis.
    static constexpr std::uint32_t kMaxCellsPerAxis = (1U << 21) - 1;

    // `cellSize` > 0 is raised when needed so that no axis of the domain has more than
    // kMaxCellsPerAxis cells. `expectedEntries` sizes the table up front.
    SpatialHashGrid(const Bounds& domain, double cellSize, std::size_t expectedEntries = 0);

    double cellSize() const { return cellSize_; }
    double reach() const { return 0.5 * cellSize_; }

    // The number of entries insert(item, bounds, ...) would make (0 when the bounds miss the domain).
    std::uint64_t entriesFor(const Bounds& bounds) const;
    void insert(std::uint32_t item, const Bounds& bounds, const Ball& ball);

    // Calls visit(item, ball) for the entries of the cells the query scans, until visit returns true;
    // returns whether it did. An item entered in several of those cells is visited once per cell.
    template <class Visit>
    bool any(const Bounds& bounds, Visit&& visit) const;

    std::size_t entryCount() const { return entries_.size(); }
    std::size_t occupiedCells() const { return occupied_; }

private:
    static constexpr std::uint32_t kEnd = 0xFFFFFFFFU;
    static constexpr std::size_t kBatch = 32;  // cells whose memory a query fetches at once
    struct Entry {
        Ball ball;
        std::uint32_t item;
        std::uint32_t next;  // next entry of the same cell, or kEnd
    };
    struct Slot {
        std::uint64_t key = 0;      // cell key + 1; 0 marks a free slot
        std::uint32_t head = kEnd;  // the cell's most recent entry
    };
    struct CellRange {
        std::array<std::uint32_t, 3> lower{};
        std::array<std::uint32_t, 3> upper{};
        bool empty = true;
    };

    CellRange cellsCovering(const Bounds& bounds) const;
    CellRange cellsOfItem(const Bounds& bounds) const;
    std::uint32_t cellCoordinate(double x, int axis) const;
    static std::uint64_t key(std::uint32_t x, std::uint32_t y, std::uint32_t z);
    static std::uint64_t hash(std::uint64_t key);
    bool mayBeOccupied(std::uint64_t hashValue) const;
    // The slot holding `key`, or the free slot it would take.
    std::size_t slotOf(std::uint64_t key, std::uint64_t hashValue) const;
    std::uint32_t firstEntry(std::uint64_t key) const;
    // The slot of `key`, taken with `head` as its first entry if the cell was empty.
    std::size_t occupy(std::uint64_t key, std::uint32_t head);
    void resizeTable(std::size_t slots);
    // A hint to start loading `address` into the cache; no effect on results.
    static void prefetch(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
        __builtin_prefetch(address);
#else
        (void)address;
#endif
    }

    Bounds domain_;
    double cellSize_;
    double inverseCellSize_;
    std::array<std::uint32_t, 3> cellsPerAxis_{};
    std::vector<Slot> slots_;
    // One bit per value of the hash's top (table bits + 2) bits, set for occupied cells: a filter with
    // at most 1 bit in 8 set, a 32nd of the table's size. Most cells a query scans are empty, and
    // this answers for them from cache.
    std::vector<std::uint64_t> occupancy_;
    std::size_t occupied_ = 0;
    int shift_ = 64;  // slot = hash >> shift_, with 2^(64 - shift_) slots
    std::vector<Entry> entries_;
};

template <class Visit>
bool SpatialHashGrid::any(const Bounds& bounds, Visit&& visit) const {
    const CellRange cells = cellsCovering(Bounds(bounds.min().array() - reach(), bounds.max().array() + reach()));
    if (cells.empty) return false;
    // Cells that pass the occupancy filter are gathered in batches: their slots are prefetched, then
    // their first entries, so that the cache misses of a batch overlap instead of queueing.
    struct Probe {
        std::uint64_t key;
        std::uint64_t hash;
        std::uint32_t head;
    };
    std::array<Probe, kBatch> batch;
    std::size_t count = 0;
    const auto visitBatch = [&] {
        for (std::size_t i = 0; i < count; ++i) {
            batch[i].head = slots_[slotOf(batch[i].key, batch[i].hash)].head;  // kEnd for a free slot
            if (batch[i].head != kEnd) prefetch(&entries_[batch[i].head]);
        }
        for (std::size_t i = 0; i < count; ++i) {
            for (std::uint32_t e = batch[i].head; e != kEnd; e = entries_[e].next) {
                if (visit(entries_[e].item, entries_[e].ball)) return true;
            }
        }
        count = 0;
        return false;
    };
    for (std::uint32_t z = cells.lower[2]; z <= cells.upper[2]; ++z) {
        for (std::uint32_t y = cells.lower[1]; y <= cells.upper[1]; ++y) {
            for (std::uint32_t x = cells.lower[0]; x <= cells.upper[0]; ++x) {
                const std::uint64_t cellKey = key(x, y, z);
                const std::uint64_t hashValue = hash(cellKey);
                if (!mayBeOccupied(hashValue)) continue;
                prefetch(&slots_[hashValue >> shift_]);
                batch[count++] = {cellKey, hashValue, kEnd};
                if (count == kBatch && visitBatch()) return true;
            }
        }
    }
    return visitBatch();
}

}  // namespace dropscope
