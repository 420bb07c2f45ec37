// Cost of one distanceToSurface call per shape type, on the same random rays, as a ratio to the
// sphere's (docs/performance.md). Run: build/bench/shape_distance_bench
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace {

using namespace dropscope;

struct Ray {
    Point origin;
    Direction direction;
};

// Rays from a shell of radius 3 towards random points of the unit ball: about half hit a unit shape.
std::vector<Ray> makeRays() {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> normal;
    std::vector<Ray> rays;
    for (int i = 0; i < 4096; ++i) {
        const Direction out(normal(rng), normal(rng), normal(rng));
        const Point target = 0.8 * Direction(normal(rng), normal(rng), normal(rng)).vector();
        const Point origin = 3.0 * out.vector();
        rays.push_back({origin, Direction(target - origin)});
    }
    return rays;
}

void runDistance(benchmark::State& state, const Shape& shape) {
    const std::vector<Ray> rays = makeRays();
    std::size_t i = 0;
    for (auto _ : state) {
        const Ray& ray = rays[i++ & 4095];
        benchmark::DoNotOptimize(shape.distanceToSurface(ray.origin, ray.direction));
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_SphereDistance(benchmark::State& state) { runDistance(state, Sphere(Point::Zero(), 1.0)); }

void BM_EllipsoidDistance(benchmark::State& state) {
    runDistance(state, Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(1.0, 0.7, 0.4),
                                               rotationAboutAxis(Direction(1, 1, 0), 0.6)));
}

void BM_BoxDistance(benchmark::State& state) { runDistance(state, Box(Point(-1, -0.7, -0.4), Point(1, 0.7, 0.4))); }

BENCHMARK(BM_SphereDistance);
BENCHMARK(BM_EllipsoidDistance);
BENCHMARK(BM_BoxDistance);

}  // namespace
