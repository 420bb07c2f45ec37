#pragma once

#include "octree/SphereCloud.hpp"
#include "tree/RayHit.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace dropscope::bench {

struct Ray {
    Point origin;
    Direction direction;
};

// Independent rays: origins uniform in the cloud's cube and outside every droplet, directions
// uniform on the unit sphere.
std::vector<Ray> randomRays(const SphereCloud& cloud, std::size_t count, std::uint64_t seed);

// The tracer's pattern: each segment starts at the previous segment's hit point p + t d (on a droplet
// surface, possibly entering it) in a new uniform direction; a segment that escapes ends the walk and
// the next starts from a fresh random point outside the droplets. `firstHit` is the exact reference
// that decides where each segment ends; every peer then traces the same stored segments.
std::vector<Ray> photonWalks(const SphereCloud& cloud, std::size_t segments, std::uint64_t seed,
                             const std::function<RayHit(const Ray&)>& firstHit);

}  // namespace dropscope::bench
