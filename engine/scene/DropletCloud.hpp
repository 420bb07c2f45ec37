#pragma once

#include "geometry/Shape.hpp"
#include "scene/RadiusDistribution.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace dropscope {

// A "droplet_cloud" generator as read from a scene (docs/scene-format.md, "Generators"): spheres of
// random radii at uniformly random places fully inside `region`, never overlapping one another or
// the shapes already in the scene. The same spec gives the same cloud on every machine (see
// RandomStream; bit-exact for the same libm).
struct DropletCloudSpec {
    Eigen::AlignedBox3d region;
    std::optional<std::uint64_t> count;    // exactly one of count and volumeFraction is set
    std::optional<double> volumeFraction;  // sum of droplet volumes / region volume
    RadiusDistribution radius = RadiusDistribution::fixed(1.0);
    std::uint64_t seed = 0;
};

struct Droplet {
    Point center;
    double radius;
};

// Densest volume_fraction accepted: random sequential placement of equal spheres jams near 0.38,
// and the last few per cent before that cost ever more attempts per droplet.
inline constexpr double kMaxDropletVolumeFraction = 0.3;
// Random places tried for one droplet before the region counts as full.
inline constexpr int kMaxAttemptsPerDroplet = 100000;

// The cloud's radii, largest first: `count` draws, or draws until their total volume reaches
// volumeFraction of the region (it ends within one droplet above it). In that mode, drawing stops
// at `limit` + 1 radii: a result longer than `limit` means the target needs more droplets than that.
std::vector<double> drawDropletRadii(const DropletCloudSpec& spec, std::size_t limit);

// The shapes a cloud must respect: ids below explicitCount are explicit shapes, inside a box or a
// sphere of which a droplet may nest (the scene's nesting rule); the others are droplets of earlier
// generators, which a droplet may only touch.
struct Obstacles {
    std::span<const std::unique_ptr<Shape>> shapes;
    std::size_t explicitCount = 0;
};

// Places droplets of `radii` in that order, each at the first of up to kMaxAttemptsPerDroplet
// uniformly random centres (in the region shrunk by its radius) that conflicts with nothing placed
// before. Stops at the first droplet that finds no place: fewer droplets than radii means the
// region filled up.
std::vector<Droplet> placeDroplets(const DropletCloudSpec& spec, std::span<const double> radii,
                                   const Obstacles& obstacles);

}  // namespace dropscope
