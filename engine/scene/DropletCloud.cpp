#include "scene/DropletCloud.hpp"

#include "geometry/Sphere.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/SpatialHashGrid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>

namespace dropscope {

namespace {

// Independent random streams of one seed: the radii do not depend on how many attempts placement took.
constexpr std::uint64_t kRadiusStream = 0;
constexpr std::uint64_t kPositionStream = 1;

// A shape already in the scene that would take more grid cells than this (a glass cell around the
// cloud, a drop much larger than this cloud's) is tested on every attempt instead, after a
// bounding-box check, so that the grid's memory stays proportional to the droplet count.
constexpr std::uint64_t kMaxGridEntriesPerObstacle = 64;
// The grid's memory: a cell size giving more entries per droplet than this is not considered.
constexpr double kMaxGridEntriesPerDroplet = 4.0;
// Radii the cell-size cost model looks at (evenly spaced in the sorted radii).
constexpr std::size_t kCostModelSamples = 256;

double sphereVolume(double radius) { return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius; }

using Bounds = Eigen::AlignedBox3d;

Bounds boundsOf(const Point& center, double radius) { return Bounds(center.array() - radius, center.array() + radius); }

// The grid cell size h that minimises the expected work of one attempt, for a cloud of `radii`
// (largest first) filling `volumeFraction` of its region. With droplets of radius r drawn from the
// same sizes as the candidates, an attempt scans about (2 + 2r/h)^3 cells, each holding on average
// phi h^3 E[entries] / E[volume] entries, where a droplet makes max(1, 2r/h)^3 entries.
double chooseCellSize(std::span<const double> radii, double volumeFraction) {
    std::vector<double> sample;
    const std::size_t step = std::max<std::size_t>(1, radii.size() / kCostModelSamples);
    for (std::size_t i = 0; i < radii.size(); i += step) sample.push_back(radii[i]);
    double meanVolume = 0.0;
    for (const double r : sample) meanVolume += sphereVolume(r) / static_cast<double>(sample.size());

    double bestSize = 2.0 * radii.front();
    double bestCost = std::numeric_limits<double>::infinity();
    // Candidates from the smallest diameter to four times the largest, in steps of 2^(1/4).
    for (double h = 2.0 * radii.back(); h <= 8.0 * radii.front(); h *= std::pow(2.0, 0.25)) {
        double scanned = 0.0;
        double entries = 0.0;
        for (const double r : sample) {
            scanned += std::pow(2.0 + 2.0 * r / h, 3);
            entries += std::pow(std::max(1.0, 2.0 * r / h), 3);
        }
        scanned /= static_cast<double>(sample.size());
        entries /= static_cast<double>(sample.size());
        if (entries > kMaxGridEntriesPerDroplet) continue;
        const double cost = scanned * (1.0 + volumeFraction * h * h * h * entries / meanVolume);
        if (cost < bestCost) {
            bestCost = cost;
            bestSize = h;
        }
    }
    return bestSize;
}

// Rejection sampling of one cloud. The grid holds the cloud's droplets and the shapes already in the
// scene (explicit ones, earlier generators' droplets) that are small next to a cell; larger ones are
// checked one by one. Grid items are scene shape ids, then the cloud's droplets.
class Placer {
public:
    using Ball = SpatialHashGrid::Ball;

    Placer(const Bounds& region, std::span<const double> radii, const Obstacles& obstacles, double volumeFraction)
        : region_(region),
          obstacles_(obstacles),
          firstDroplet_(static_cast<std::uint32_t>(obstacles.shapes.size())),
          grid_(region, chooseCellSize(radii, volumeFraction), radii.size() + obstacles.shapes.size()) {
        droplets_.reserve(radii.size());
        for (std::size_t id = 0; id < obstacles.shapes.size(); ++id) {
            const Shape& shape = *obstacles.shapes[id];
            const Bounds bounds = shape.bounds();
            const std::uint64_t entries = grid_.entriesFor(bounds);
            if (entries == 0) continue;  // outside the region: no droplet can reach it
            const auto item = static_cast<std::uint32_t>(id);
            Ball ball{bounds.center(), 0.5 * bounds.diagonal().norm()};  // unused for explicit shapes
            if (id >= obstacles.explicitCount) {
                const auto& sphere = static_cast<const Sphere&>(shape);  // an earlier generator's droplet
                ball = {sphere.center(), sphere.radius()};
            }
            if (entries > kMaxGridEntriesPerObstacle) {
                largeObstacles_.push_back({item, bounds, ball});
            } else {
                grid_.insert(item, bounds, ball);
            }
        }
    }

    // Tries random centres for a droplet of `radius`; keeps the first free one.
    bool place(double radius, RandomStream& random) {
        const Point lowest = region_.min().array() + radius;
        const Point highest = region_.max().array() - radius;
        for (int attempt = 0; attempt < kMaxAttemptsPerDroplet; ++attempt) {
            Point center;
            for (int axis = 0; axis < 3; ++axis) {
                // The product on its own, so that no fused multiply-add changes the rounding.
                const double offset = random.uniform() * (highest[axis] - lowest[axis]);
                center[axis] = std::clamp(lowest[axis] + offset, lowest[axis], highest[axis]);
            }
            if (conflicts(center, radius)) continue;
            grid_.insert(firstDroplet_ + static_cast<std::uint32_t>(droplets_.size()), boundsOf(center, radius),
                         {center, radius});
            droplets_.push_back({center, radius});
            return true;
        }
        return false;
    }

    std::vector<Droplet> take() { return std::move(droplets_); }

private:
    bool conflicts(const Point& center, double radius) const {
        std::optional<Sphere> candidate;  // built only when an explicit shape needs the exact test
        // Explicit shapes: the scene's own overlap rule, with the droplet as the nested one.
        const auto conflictsWithExplicit = [&](std::uint32_t id) {
            if (!candidate) candidate.emplace(center, radius);
            const Shape& shape = *obstacles_.shapes[id];
            return shape.overlaps(*candidate) && !nestsInside(*candidate, shape);
        };
        const auto conflictsWith = [&](std::uint32_t item, const Ball& ball) {
            if (item < obstacles_.explicitCount) return conflictsWithExplicit(item);
            return ballsIntersect(ball, center, radius);  // a droplet, of this cloud or an earlier one
        };
        const Bounds bounds = boundsOf(center, radius);
        if (grid_.any(bounds, conflictsWith)) return true;
        return std::any_of(largeObstacles_.begin(), largeObstacles_.end(), [&](const LargeObstacle& large) {
            return bounds.intersects(large.bounds) && conflictsWith(large.id, large.ball);
        });
    }

    // Positive volume of intersection between droplets; touching is allowed.
    static bool ballsIntersect(const Ball& ball, const Point& center, double radius) {
        const double reach = ball.radius + radius;
        return (ball.center - center).squaredNorm() < reach * reach;
    }

    struct LargeObstacle {
        std::uint32_t id;
        Bounds bounds;
        Ball ball;
    };

    Bounds region_;
    Obstacles obstacles_;
    std::uint32_t firstDroplet_;  // grid item of the cloud's first droplet
    SpatialHashGrid grid_;
    std::vector<LargeObstacle> largeObstacles_;
    std::vector<Droplet> droplets_;
};

}  // namespace

std::vector<double> drawDropletRadii(const DropletCloudSpec& spec, std::size_t limit) {
    RandomStream random(spec.seed, kRadiusStream);
    std::vector<double> radii;
    if (spec.count) {
        radii.reserve(*spec.count);
        for (std::uint64_t i = 0; i < *spec.count; ++i) radii.push_back(spec.radius.sample(random));
    } else {
        const double target = *spec.volumeFraction * spec.region.volume();
        double volume = 0.0;
        while (volume < target) {
            if (radii.size() > limit) return radii;  // over the limit: the caller refuses, no need to sort
            radii.push_back(spec.radius.sample(random));
            volume += sphereVolume(radii.back());
        }
    }
    std::sort(radii.begin(), radii.end(), std::greater<>());
    return radii;
}

std::vector<Droplet> placeDroplets(const DropletCloudSpec& spec, std::span<const double> radii,
                                   const Obstacles& obstacles) {
    if (radii.empty()) return {};
    double volume = 0.0;
    for (const double r : radii) volume += sphereVolume(r);
    Placer placer(spec.region, radii, obstacles, volume / spec.region.volume());
    RandomStream random(spec.seed, kPositionStream);
    for (const double radius : radii) {
        if (!placer.place(radius, random)) break;
    }
    return placer.take();
}

}  // namespace dropscope
