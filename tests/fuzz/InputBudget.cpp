#include "InputBudget.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope::fuzz {

namespace {

using nlohmann::json;

// `object[key]` as a number, or NaN when it is missing or not a number.
double numberAt(const json& object, const char* key) {
    if (!object.is_object()) return std::nan("");
    const auto found = object.find(key);
    return found != object.end() && found->is_number() ? found->get<double>() : std::nan("");
}

// The volume of {"min": [x, y, z], "max": [x, y, z]}, or NaN.
double regionVolume(const json& region) {
    if (!region.is_object() || !region.contains("min") || !region.contains("max")) return std::nan("");
    const json& min = region["min"];
    const json& max = region["max"];
    if (!min.is_array() || !max.is_array() || min.size() != 3 || max.size() != 3) return std::nan("");
    double volume = 1.0;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!min[axis].is_number() || !max[axis].is_number()) return std::nan("");
        volume *= std::max(0.0, max[axis].get<double>() - min[axis].get<double>());
    }
    return volume;
}

// A radius the distribution draws smaller ones than rarely: the droplets of a volume fraction are counted as if
// all were this small. Truncated distributions use their "min" when it is larger.
double smallRadius(const json& radius) {
    if (!radius.is_object() || !radius.contains("distribution") || !radius["distribution"].is_string())
        return std::nan("");
    const std::string kind = radius["distribution"].get<std::string>();
    const double min = numberAt(radius, "min");
    if (kind == "fixed") return numberAt(radius, "value");
    if (kind == "uniform") return min;
    double tail = std::nan("");  // about the first percentile of the unbounded distribution
    if (kind == "lognormal") tail = numberAt(radius, "median") * std::exp(-3.0 * numberAt(radius, "sigma"));
    if (kind == "rosin_rammler") tail = numberAt(radius, "scale") * std::pow(0.01, 1.0 / numberAt(radius, "shape"));
    return std::isnan(min) ? tail : std::max(min, tail);
}

// The droplets one generator asks for (0 when it cannot be told).
double dropletsAsked(const json& generator) {
    const double count = numberAt(generator, "count");
    if (!std::isnan(count)) return std::max(count, 0.0);
    const double fraction = numberAt(generator, "volume_fraction");
    if (std::isnan(fraction) || !generator.contains("region") || !generator.contains("radius")) return 0.0;
    const double r = smallRadius(generator["radius"]);
    if (std::isnan(r) || r < 0.0) return 0.0;  // no radius, or one the loader refuses; 0 counts as infinitely many
    const double droplets = fraction * regionVolume(generator["region"]) / (4.0 / 3.0 * std::numbers::pi * r * r * r);
    return std::isnan(droplets) ? 0.0 : std::max(droplets, 0.0);
}

// The terms of the implicit shapes of "shapes": a blob's centers, 1 for any other.
double implicitTerms(const json& shapes) {
    double terms = 0.0;
    for (const json& shape : shapes) {
        if (!shape.is_object() || !shape.contains("type") || shape["type"] != "implicit") continue;
        const auto centers = shape.find("centers");
        terms += centers != shape.end() && centers->is_array() ? static_cast<double>(centers->size()) : 1.0;
    }
    return terms;
}

}  // namespace

bool withinInputBudget(std::string_view sceneText) {
    // A patches file on a device (/dev/zero, /dev/urandom) is read up to the loader's 1 GiB limit: seconds and a
    // gigabyte per input. The CTest cli_patches_file_too_large covers it once.
    if (sceneText.find("/dev/") != std::string_view::npos || sceneText.find("/proc/") != std::string_view::npos)
        return false;
    // The common case, without a parse.
    if (sceneText.find("generators") == std::string_view::npos && sceneText.find("implicit") == std::string_view::npos)
        return true;
    const json scene = json::parse(sceneText, nullptr, /*allow_exceptions=*/false);
    if (!scene.is_object()) return true;
    double droplets = 0.0;
    if (scene.contains("generators") && scene["generators"].is_array()) {
        for (const json& generator : scene["generators"]) droplets += dropletsAsked(generator);
    }
    const double terms = scene.contains("shapes") && scene["shapes"].is_array() ? implicitTerms(scene["shapes"]) : 0.0;
    return droplets <= kMaxFuzzedDroplets && terms <= kMaxFuzzedImplicitTerms;
}

}  // namespace dropscope::fuzz
