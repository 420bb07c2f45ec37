#include "scene/SpatialHashGrid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace dropscope {

namespace {

constexpr std::size_t kMinSlots = 16;
constexpr std::uint64_t kFibonacciMultiplier = 0x9E3779B97F4A7C15ULL;  // 2^64 / golden ratio
// The occupancy filter has 2^kOccupancyExtraBits bits per table slot: at most 1 in 8 set.
constexpr int kOccupancyExtraBits = 2;

}  // namespace

SpatialHashGrid::SpatialHashGrid(const Bounds& domain, double cellSize, std::size_t expectedEntries) : domain_(domain) {
    if (!(cellSize > 0.0) || domain.isEmpty()) throw std::invalid_argument("SpatialHashGrid: bad domain or cell size");
    const Eigen::Vector3d extent = domain.sizes();
    cellSize_ = std::max(cellSize, extent.maxCoeff() / (kMaxCellsPerAxis - 1));
    inverseCellSize_ = 1.0 / cellSize_;
    for (int axis = 0; axis < 3; ++axis) {
        const double cells = std::ceil(extent[axis] * inverseCellSize_);
        cellsPerAxis_[static_cast<std::size_t>(axis)] =
            static_cast<std::uint32_t>(std::clamp(cells, 1.0, static_cast<double>(kMaxCellsPerAxis)));
    }
    resizeTable(std::bit_ceil(std::max(kMinSlots, 2 * expectedEntries)));
    entries_.reserve(expectedEntries);
}

std::uint32_t SpatialHashGrid::cellCoordinate(double x, int axis) const {
    const double cell = std::floor((x - domain_.min()[axis]) * inverseCellSize_);
    const double last = static_cast<double>(cellsPerAxis_[static_cast<std::size_t>(axis)] - 1);
    return static_cast<std::uint32_t>(std::clamp(cell, 0.0, last));
}

SpatialHashGrid::CellRange SpatialHashGrid::cellsCovering(const Bounds& bounds) const {
    CellRange range;
    if (!bounds.intersects(domain_)) return range;
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = static_cast<std::size_t>(axis);
        range.lower[a] = cellCoordinate(bounds.min()[axis], axis);
        range.upper[a] = cellCoordinate(bounds.max()[axis], axis);
    }
    range.empty = false;
    return range;
}

SpatialHashGrid::CellRange SpatialHashGrid::cellsOfItem(const Bounds& bounds) const {
    if (!bounds.intersects(domain_)) return {};
    // Shrink by reach on each side, down to the centre for an item no wider than a cell. Rounding is
    // monotone, so an item and a query whose bounds intersect still meet in a cell.
    Bounds shrunk;
    for (int axis = 0; axis < 3; ++axis) {
        const double lower = bounds.min()[axis];
        const double upper = bounds.max()[axis];
        if (upper - lower <= cellSize_) {
            shrunk.min()[axis] = shrunk.max()[axis] = 0.5 * (lower + upper);
        } else {
            shrunk.min()[axis] = lower + reach();
            shrunk.max()[axis] = upper - reach();
        }
    }
    // A centre outside the domain lands in its border cell: cellCoordinate clamps, as for queries.
    CellRange range;
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = static_cast<std::size_t>(axis);
        range.lower[a] = cellCoordinate(shrunk.min()[axis], axis);
        range.upper[a] = cellCoordinate(shrunk.max()[axis], axis);
    }
    range.empty = false;
    return range;
}

std::uint64_t SpatialHashGrid::entriesFor(const Bounds& bounds) const {
    const CellRange cells = cellsOfItem(bounds);
    if (cells.empty) return 0;
    std::uint64_t count = 1;
    for (std::size_t a = 0; a < 3; ++a) count *= cells.upper[a] - cells.lower[a] + 1ULL;
    return count;
}

std::uint64_t SpatialHashGrid::key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return std::uint64_t{x} | (std::uint64_t{y} << 21) | (std::uint64_t{z} << 42);
}

std::uint64_t SpatialHashGrid::hash(std::uint64_t cellKey) { return cellKey * kFibonacciMultiplier; }

bool SpatialHashGrid::mayBeOccupied(std::uint64_t hashValue) const {
    const std::uint64_t bit = hashValue >> (shift_ - kOccupancyExtraBits);
    return ((occupancy_[bit >> 6] >> (bit & 63)) & 1U) != 0;
}

std::size_t SpatialHashGrid::slotOf(std::uint64_t cellKey, std::uint64_t hashValue) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t slot = static_cast<std::size_t>(hashValue >> shift_);
    while (slots_[slot].key != 0 && slots_[slot].key != cellKey + 1) slot = (slot + 1) & mask;  // linear probing
    return slot;
}

std::uint32_t SpatialHashGrid::firstEntry(std::uint64_t cellKey) const {
    const std::uint64_t hashValue = hash(cellKey);
    if (!mayBeOccupied(hashValue)) return kEnd;
    return slots_[slotOf(cellKey, hashValue)].head;  // kEnd for a free slot
}

std::size_t SpatialHashGrid::occupy(std::uint64_t cellKey, std::uint32_t head) {
    const std::uint64_t hashValue = hash(cellKey);
    const std::size_t slot = slotOf(cellKey, hashValue);
    if (slots_[slot].key == 0) {
        slots_[slot] = {cellKey + 1, head};
        ++occupied_;
        const std::uint64_t bit = hashValue >> (shift_ - kOccupancyExtraBits);
        occupancy_[bit >> 6] |= std::uint64_t{1} << (bit & 63);
    }
    return slot;
}

void SpatialHashGrid::resizeTable(std::size_t slotCount) {
    std::vector<Slot> previous(slotCount);
    slots_.swap(previous);
    occupancy_.assign(std::max<std::size_t>(1, (slotCount << kOccupancyExtraBits) / 64), 0);
    shift_ = 64 - std::countr_zero(slotCount);
    occupied_ = 0;
    for (const Slot& slot : previous) {
        if (slot.key != 0) occupy(slot.key - 1, slot.head);
    }
}

void SpatialHashGrid::insert(std::uint32_t item, const Bounds& bounds, const Ball& ball) {
    const CellRange cells = cellsOfItem(bounds);
    if (cells.empty) return;
    for (std::uint32_t z = cells.lower[2]; z <= cells.upper[2]; ++z) {
        for (std::uint32_t y = cells.lower[1]; y <= cells.upper[1]; ++y) {
            for (std::uint32_t x = cells.lower[0]; x <= cells.upper[0]; ++x) {
                if (entries_.size() >= kEnd) throw std::length_error("SpatialHashGrid: too many entries");
                if (2 * (occupied_ + 1) > slots_.size()) resizeTable(2 * slots_.size());  // load factor <= 1/2
                const std::size_t slot = occupy(key(x, y, z), kEnd);
                entries_.push_back({ball, item, slots_[slot].head});
                slots_[slot].head = static_cast<std::uint32_t>(entries_.size() - 1);
            }
        }
    }
}

}  // namespace dropscope
