#include "scene/GeneratorReader.hpp"

#include "geometry/Sphere.hpp"
#include "scene/DropletCloud.hpp"
#include "scene/JsonPath.hpp"
#include "scene/MachineMemory.hpp"
#include "scene/MediaReader.hpp"
#include "scene/ShapeReader.hpp"

#include <charconv>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

// Radii below this fraction of the region's scale (its largest side or coordinate) would be lost in
// the rounding of their own coordinates (tolerance::kCoordinateRelative).
constexpr double kMinRadiusRelative = 1e-9;

// `value` to two significant digits, for messages ("0.31").
std::string roughly(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 2);
    return std::string(buffer, result.ptr);
}

// {"min": [..], "max": [..]} with min < max on every axis.
Eigen::AlignedBox3d readRegion(const JsonReader& json) {
    json.expectKeys({"min", "max"});
    return readCorners(json);
}

// The optional truncation [min, max] of an unbounded distribution. A struct, not a pair taken apart by a
// structured binding: the lambdas below capture its members, which clang 14 (the sanitizer build) cannot do for
// the names of a binding.
struct Truncation {
    double min;
    double max;
};

Truncation readTruncation(const JsonReader& json) {
    const auto minJson = json.optionalMember("min");
    const auto maxJson = json.optionalMember("max");
    const double min = minJson ? minJson->nonNegative() : 0.0;
    const double max = maxJson ? maxJson->positive() : RadiusDistribution::kUnbounded;
    if (maxJson && !(max > min)) maxJson->fail("must be > \"min\"");
    return {min, max};
}

RadiusDistribution readRadiusDistribution(const JsonReader& json) {
    const JsonReader kindJson = json.member("distribution");
    const std::string kind = kindJson.string();
    if (kind == "fixed") {
        json.expectKeys({"distribution", "value"});
        return RadiusDistribution::fixed(json.member("value").positive());
    }
    if (kind == "uniform") {
        json.expectKeys({"distribution", "min", "max"});
        const double min = json.member("min").positive();
        const JsonReader maxJson = json.member("max");
        const double max = maxJson.positive();
        if (!(max > min)) maxJson.fail("must be > \"min\"");
        return RadiusDistribution::uniform(min, max);
    }
    if (kind == "lognormal") {
        json.expectKeys({"distribution", "median", "sigma", "min", "max"});
        const double median = json.member("median").positive();
        const double sigma = json.member("sigma").nonNegative();
        const Truncation truncation = readTruncation(json);
        return json.construct(
            [&] { return RadiusDistribution::lognormal(median, sigma, truncation.min, truncation.max); });
    }
    if (kind == "rosin_rammler") {
        json.expectKeys({"distribution", "scale", "shape", "min", "max"});
        const double scale = json.member("scale").positive();
        const double shape = json.member("shape").positive();
        const Truncation truncation = readTruncation(json);
        return json.construct(
            [&] { return RadiusDistribution::rosinRammler(scale, shape, truncation.min, truncation.max); });
    }
    kindJson.fail("unknown distribution " + jsonpath::quoted(kind) +
                  " (known: fixed, uniform, lognormal, rosin_rammler)");
}

DropletCloudSpec readDropletCloudSpec(const JsonReader& json, std::size_t budget, std::size_t generated) {
    json.expectKeys({"type", "region", "count", "volume_fraction", "radius", "medium", "seed"});
    DropletCloudSpec spec;
    spec.region = readRegion(json.member("region"));
    const auto countJson = json.optionalMember("count");
    const auto fractionJson = json.optionalMember("volume_fraction");
    if (countJson && fractionJson) json.fail("give either \"count\" or \"volume_fraction\", not both");
    if (countJson) {
        const std::int64_t count = countJson->integer();
        if (count < 0) countJson->fail("must be >= 0");
        if (static_cast<std::uint64_t>(count) > budget) {
            countJson->fail("must be <= " + std::to_string(budget) + " (a scene generates at most " +
                            std::to_string(kMaxGeneratedDroplets) + " droplets; " + std::to_string(generated) +
                            " already generated)");
        }
        spec.count = static_cast<std::uint64_t>(count);
    } else if (fractionJson) {
        spec.volumeFraction = fractionJson->positive();
        if (*spec.volumeFraction > kMaxDropletVolumeFraction) {
            fractionJson->fail("must be <= " + jsonpath::number(kMaxDropletVolumeFraction) +
                               " (denser random packings jam; see docs/scene-format.md)");
        }
    } else {
        json.fail("missing required key \"count\" or \"volume_fraction\"");
    }
    spec.radius = readRadiusDistribution(json.member("radius"));
    if (const auto seed = json.optionalMember("seed")) {
        const std::int64_t value = seed->integer();
        if (value < 0) seed->fail("must be >= 0");
        spec.seed = static_cast<std::uint64_t>(value);
    }
    return spec;
}

// The drawn radii must make sense in the region: the largest must fit, the smallest must not vanish.
void checkRadii(const JsonReader& json, const DropletCloudSpec& spec, const std::vector<double>& radii) {
    if (radii.empty()) return;
    const JsonReader radiusJson = json.member("radius");
    const Eigen::Vector3d sides = spec.region.sizes();
    if (2.0 * radii.front() > sides.minCoeff()) {
        const bool unbounded = spec.radius.max() == RadiusDistribution::kUnbounded;
        radiusJson.fail("a droplet of radius " + roughly(radii.front()) +
                        " does not fit in the region (its smallest side is " + jsonpath::number(sides.minCoeff()) +
                        (unbounded ? "); bound the radii with \"max\"" : ")"));
    }
    if (radii.back() < kMinRadiusRelative * std::max(sides.maxCoeff(), largestCoordinate(spec.region))) {
        radiusJson.fail("a droplet of radius " + roughly(radii.back()) + " is too small for the region (radii must " +
                        "be >= " + jsonpath::number(kMinRadiusRelative) +
                        " of its largest side or coordinate); bound the radii with \"min\"");
    }
}

std::vector<Droplet> runDropletCloud(const JsonReader& json, const DropletCloudSpec& spec, const Scene& scene,
                                     std::size_t budget) {
    const std::vector<double> radii = drawDropletRadii(spec, budget);
    if (radii.size() > budget) {
        json.member("volume_fraction")
            .fail("needs more than " + std::to_string(budget) + " droplets of this size (a scene generates at most " +
                  std::to_string(kMaxGeneratedDroplets) + "); use larger radii or a smaller region");
    }
    checkRadii(json, spec, radii);
    // Refused before placing: a cloud the machine cannot hold would otherwise end in an allocation failure
    // (or the kernel's OOM killer) minutes in.
    if (const auto problem = cloudMemoryProblem(scene.shapes.size(), radii.size()))
        json.member(spec.count ? "count" : "volume_fraction").fail(*problem);
    std::vector<Droplet> droplets = placeDroplets(spec, radii, {scene.shapes, scene.explicitShapeCount});
    if (droplets.size() < radii.size()) {
        double volume = 0.0;
        for (const Droplet& d : droplets) volume += 4.0 / 3.0 * std::numbers::pi * d.radius * d.radius * d.radius;
        json.fail("placed " + std::to_string(droplets.size()) + " of " + std::to_string(radii.size()) +
                  " droplets before the region filled (volume fraction reached " +
                  roughly(volume / spec.region.volume()) + "); lower count or volume_fraction");
    }
    return droplets;
}

}  // namespace

void readGenerators(const JsonReader& generators, Scene& scene) {
    for (const JsonReader& json : generators.elements()) {
        const JsonReader typeJson = json.member("type");
        const std::string type = typeJson.string();
        if (type != "droplet_cloud") {
            typeJson.fail("unknown generator type " + jsonpath::quoted(type) + " (known: droplet_cloud)");
        }
        const std::size_t generated = scene.shapes.size() - scene.explicitShapeCount;
        const std::size_t budget = kMaxGeneratedDroplets - generated;
        const DropletCloudSpec spec = readDropletCloudSpec(json, budget, generated);
        const MediumId medium = readMediumName(json.member("medium"), scene.media);
        const std::vector<Droplet> droplets = runDropletCloud(json, spec, scene, budget);
        scene.generators.push_back({spec.radius, medium, scene.shapes.size(), droplets.size()});
        scene.shapes.reserve(scene.shapes.size() + droplets.size());
        scene.shapeNames.resize(scene.shapeNames.size() + droplets.size());
        for (const Droplet& droplet : droplets) {
            auto sphere = std::make_unique<Sphere>(droplet.center, droplet.radius);
            sphere->setMediumId(medium);
            scene.shapes.push_back(std::move(sphere));
        }
    }
}

}  // namespace dropscope
