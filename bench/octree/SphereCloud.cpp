#include "octree/SphereCloud.hpp"

#include <bit>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace dropscope::bench {

namespace {
// Rejections allowed per droplet placed before the cube is declared too crowded.
constexpr std::size_t kAttemptsPerDroplet = 1000;
}  // namespace

SphereCloud::SphereCloud(const CloudSpec& spec)
    : spec_(spec),
      // Any droplet that can touch a new one has its centre within 2 * maxRadius (plus clearance):
      // one cell, so the 27 cells around the new centre hold every candidate.
      cell_(2.0 * spec.maxRadius * (1.0 + 4.0 * kClearance)),
      head_(std::bit_ceil(2 * spec.count + 1), kEnd) {
    if (!(spec.minRadius > 0.0 && spec.maxRadius >= spec.minRadius && spec.halfSide > spec.maxRadius)) {
        throw std::invalid_argument("SphereCloud: need 0 < minRadius <= maxRadius < halfSide");
    }
    droplets_.reserve(spec.count);
    next_.reserve(spec.count);
    std::mt19937_64 rng(spec.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t attempts = 0;
    while (droplets_.size() < spec.count) {
        if (++attempts > kAttemptsPerDroplet * spec.count) {
            throw std::runtime_error("SphereCloud: placed only " + std::to_string(droplets_.size()) + " of " +
                                     std::to_string(spec.count) + " droplets");
        }
        const double radius = spec.minRadius + (spec.maxRadius - spec.minRadius) * unit(rng);
        const double reach = spec.halfSide - radius;  // the centre range keeping the droplet in the cube
        const Point center(reach * (2.0 * unit(rng) - 1.0), reach * (2.0 * unit(rng) - 1.0),
                           reach * (2.0 * unit(rng) - 1.0));
        if (isClear(center, radius)) add({center, radius});
    }
}

std::int64_t SphereCloud::cellOf(double x) const { return static_cast<std::int64_t>(std::floor(x / cell_)); }

std::size_t SphereCloud::bucketOf(std::int64_t ix, std::int64_t iy, std::int64_t iz) const {
    // Large odd multipliers spread neighbouring cells over the table; collisions only add candidates.
    const auto h = static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ull ^
                   static_cast<std::uint64_t>(iy) * 0xC2B2AE3D27D4EB4Full ^
                   static_cast<std::uint64_t>(iz) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>((h ^ (h >> 29)) & (head_.size() - 1));
}

void SphereCloud::add(const Droplet& droplet) {
    const auto index = static_cast<std::uint32_t>(droplets_.size());
    const std::size_t bucket =
        bucketOf(cellOf(droplet.center.x()), cellOf(droplet.center.y()), cellOf(droplet.center.z()));
    droplets_.push_back(droplet);
    next_.push_back(head_[bucket]);
    head_[bucket] = index;
}

// No stored droplet within (radius + its radius)(1 + kClearance) of `center`; radius 0 tests a point.
bool SphereCloud::isClear(const Point& center, double radius) const {
    const std::int64_t cx = cellOf(center.x());
    const std::int64_t cy = cellOf(center.y());
    const std::int64_t cz = cellOf(center.z());
    for (std::int64_t ix = cx - 1; ix <= cx + 1; ++ix) {
        for (std::int64_t iy = cy - 1; iy <= cy + 1; ++iy) {
            for (std::int64_t iz = cz - 1; iz <= cz + 1; ++iz) {
                for (std::uint32_t k = head_[bucketOf(ix, iy, iz)]; k != kEnd; k = next_[k]) {
                    const double reach = (radius + droplets_[k].radius) * (1.0 + kClearance);
                    if ((droplets_[k].center - center).squaredNorm() <= reach * reach) return false;
                }
            }
        }
    }
    return true;
}

bool SphereCloud::isOutsideAll(const Point& p) const { return isClear(p, 0.0); }

}  // namespace dropscope::bench
