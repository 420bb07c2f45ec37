#pragma once

#include "geometry/Vector.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dropscope::bench {

struct Droplet {
    Point center;
    double radius;
};

// What to place: `count` droplets, radii uniform in [minRadius, maxRadius], wholly inside the cube
// [-halfSide, halfSide]^3.
struct CloudSpec {
    std::size_t count;
    double halfSide;
    double minRadius;
    double maxRadius;
    std::uint64_t seed;
};

// A random non-overlapping sphere cloud for the benchmark only (engine/scene has the real generator):
// rejection sampling against a uniform hash grid of cell 2 * maxRadius, so a new droplet is checked
// against the droplets of the 27 cells around its centre. The grid stays, for isOutsideAll().
class SphereCloud {
public:
    // Throws std::runtime_error when the cube is too crowded to place `count` droplets.
    explicit SphereCloud(const CloudSpec& spec);

    const std::vector<Droplet>& droplets() const { return droplets_; }
    double halfSide() const { return spec_.halfSide; }

    // Clear of every droplet by kClearance of its radius: a ray origin that every shape classifies
    // as Outside, far from any surface band.
    bool isOutsideAll(const Point& p) const;

    // Gaps between droplets, and between ray origins and droplets, are at least this fraction of the
    // radii involved (1e-6: a million times a sphere's surface band, invisible at the figures' scale).
    static constexpr double kClearance = 1e-6;

private:
    bool isClear(const Point& center, double radius) const;
    void add(const Droplet& droplet);
    std::int64_t cellOf(double x) const;
    std::size_t bucketOf(std::int64_t ix, std::int64_t iy, std::int64_t iz) const;

    static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;

    CloudSpec spec_;
    double cell_;
    std::vector<Droplet> droplets_;
    std::vector<std::uint32_t> head_;  // per bucket: the last droplet added to it, or kEnd
    std::vector<std::uint32_t> next_;  // per droplet: the previous droplet of its bucket, or kEnd
};

}  // namespace dropscope::bench
