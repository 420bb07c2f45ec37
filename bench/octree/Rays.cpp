#include "octree/Rays.hpp"

#include <random>

namespace dropscope::bench {

namespace {

Direction randomDirection(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    while (true) {
        const Direction d(normal(rng), normal(rng), normal(rng));
        if (d) return d;  // a zero draw has no direction
    }
}

Point randomOutsidePoint(const SphereCloud& cloud, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coordinate(-cloud.halfSide(), cloud.halfSide());
    while (true) {
        const Point p(coordinate(rng), coordinate(rng), coordinate(rng));
        if (cloud.isOutsideAll(p)) return p;
    }
}

}  // namespace

std::vector<Ray> randomRays(const SphereCloud& cloud, std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Ray> rays;
    rays.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Point origin = randomOutsidePoint(cloud, rng);
        rays.push_back({origin, randomDirection(rng)});
    }
    return rays;
}

std::vector<Ray> photonWalks(const SphereCloud& cloud, std::size_t segments, std::uint64_t seed,
                             const std::function<RayHit(const Ray&)>& firstHit) {
    std::mt19937_64 rng(seed);
    std::vector<Ray> rays;
    rays.reserve(segments);
    Point origin = randomOutsidePoint(cloud, rng);
    while (rays.size() < segments) {
        const Ray ray{origin, randomDirection(rng)};
        rays.push_back(ray);
        const RayHit hit = firstHit(ray);
        origin = hit ? Point(ray.origin + hit.distance * ray.direction.vector()) : randomOutsidePoint(cloud, rng);
    }
    return rays;
}

}  // namespace dropscope::bench
