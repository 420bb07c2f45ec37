#include "scene/SceneLimits.hpp"

#include "geometry/GeneralShape.hpp"
#include "scene/JsonPath.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLoader.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

namespace dropscope {

namespace {

// Three significant digits, for messages: "1e+300", "0.3", "inf".
std::string roughly(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// A point's reach with a radius around it; NaN stays NaN so that the caller's checks catch it.
double reachOf(const Point& point, double radius) { return point.cwiseAbs().maxCoeff() + radius; }

// Where a shape is in the file and what it is: {"shapes[3]", "sphere \"d1\""}, or {"generators[0]", "droplet 17"}.
struct ShapePlace {
    std::string path;
    std::string what;
    std::string text() const { return path + ": " + what; }
};

ShapePlace shapePlace(const Scene& scene, std::size_t id) {
    for (std::size_t g = 0; g < scene.generators.size(); ++g) {
        const GeneratedCloud& cloud = scene.generators[g];
        if (id >= cloud.firstShape && id < cloud.firstShape + cloud.count) {
            return {jsonpath::element("generators", g), "droplet " + std::to_string(id - cloud.firstShape)};
        }
    }
    std::string what = shapeTypeLabel(*scene.shapes[id]);
    if (id < scene.shapeNames.size() && !scene.shapeNames[id].empty())
        what.append(" ").append(jsonpath::quoted(scene.shapeNames[id]));
    return {jsonpath::element("shapes", id), what};
}

double sourceReach(const Source& source) {
    return reachOf(source.origin, source.type == SourceType::Beam ? source.radius : 0.0);
}

double detectorReach(const Detector& detector) {
    if (detector.type != DetectorType::Plane) return 0.0;
    return reachOf(detector.center, 0.5 * std::hypot(detector.size[0], detector.size[1]));
}

}  // namespace

std::string beyondCoordinateLimit() {
    return "beyond the limit " + roughly(kMaxCoordinate) + " on any coordinate (docs/limits.md)";
}

std::string shapeLabel(const Scene& scene, std::size_t id) {
    if (id >= scene.shapes.size()) return "shape " + std::to_string(id);
    return shapePlace(scene, id).text();
}

double smallestFeature(const Shape& shape) { return 3.0 * shape.volume() / shape.surfaceArea(); }

std::optional<std::string> shapeLimitProblem(const Shape& shape) {
    const Eigen::AlignedBox3d bounds = shape.bounds();
    if (!bounds.min().allFinite() || !bounds.max().allFinite()) return "its bounds are not finite (docs/limits.md)";
    const double reach = largestCoordinate(bounds);
    if (reach > kMaxCoordinate) {
        return "its bounds reach " + roughly(reach) + ", " + beyondCoordinateLimit();
    }
    const double volume = shape.volume();
    const double area = shape.surfaceArea();
    if (!(std::isfinite(volume) && volume > 0.0))
        return "its volume is " + roughly(volume) + ", not finite and > 0 (docs/limits.md)";
    if (!(std::isfinite(area) && area > 0.0))
        return "its surface area is " + roughly(area) + ", not finite and > 0 (docs/limits.md)";
    const double feature = smallestFeature(shape);
    if (!(feature >= kMinFeature)) {
        return "its smallest feature (3 volume / area) " + roughly(feature) + " is below the limit " +
               roughly(kMinFeature) + " (docs/limits.md)";
    }
    return std::nullopt;
}

std::optional<std::string> sourceLimitProblem(const Source& source) {
    const double reach = sourceReach(source);
    if (reach <= kMaxCoordinate) return std::nullopt;
    return "it reaches " + roughly(reach) + " (origin plus radius), " + beyondCoordinateLimit();
}

std::optional<std::string> detectorLimitProblem(const Detector& detector) {
    const double reach = detectorReach(detector);
    if (reach <= kMaxCoordinate) return std::nullopt;
    return "it reaches " + roughly(reach) + " (centre plus half the diagonal), " + beyondCoordinateLimit();
}

void checkSourceAndDetectorLimits(const Scene& scene) {
    for (std::size_t i = 0; i < scene.sources.size(); ++i) {
        if (const auto problem = sourceLimitProblem(scene.sources[i])) {
            throw SceneError(scene.origin, jsonpath::element("sources", i), *problem);
        }
    }
    for (std::size_t i = 0; i < scene.detectors.size(); ++i) {
        if (const auto problem = detectorLimitProblem(scene.detectors[i])) {
            throw SceneError(scene.origin, jsonpath::element("detectors", i), *problem);
        }
    }
}

void ScaleExtremes::add(const Shape& shape) {
    reach = std::max(reach, largestCoordinate(shape.bounds()));
    feature = std::min(feature, smallestFeature(shape));
}

void ScaleExtremes::add(const Source& source) { reach = std::max(reach, sourceReach(source)); }

void ScaleExtremes::add(const Detector& detector) { reach = std::max(reach, detectorReach(detector)); }

std::string scaleLimitMessage(double feature, double reach, const std::string& unit, const std::string& where) {
    return "its smallest feature (3 volume / area) " + roughly(feature) + " " + unit + " is " +
           roughly(reach / feature) + " times smaller than the scene's reach " + roughly(reach) + " " + unit + " (" +
           where + "); the limit is " + roughly(kMaxScaleRatio) +
           ", beyond which double precision cannot tell its surface from its inside (docs/limits.md)";
}

void checkSceneScale(const Scene& scene) {
    if (scene.shapes.empty()) return;
    ScaleExtremes extremes;
    std::function<std::string()> reachPlace;
    std::size_t finest = 0;
    // Remembers where the reach came from when `add` moved it, and which shape has the smallest feature.
    const auto note = [&](double before, std::function<std::string()> where) {
        if (extremes.reach > before) reachPlace = std::move(where);
    };
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const Shape& shape = *scene.shapes[id];
        if (const auto problem = shapeLimitProblem(shape)) {
            const ShapePlace place = shapePlace(scene, id);
            throw SceneError(scene.origin, place.path, place.what + ": " + *problem);
        }
        const double reach = extremes.reach;
        const double feature = extremes.feature;
        extremes.add(shape);
        note(reach, [&scene, id] { return shapePlace(scene, id).text(); });
        if (extremes.feature < feature) finest = id;
    }
    for (std::size_t i = 0; i < scene.sources.size(); ++i) {
        const double reach = extremes.reach;
        extremes.add(scene.sources[i]);
        note(reach, [i] { return jsonpath::element("sources", i); });
    }
    for (std::size_t i = 0; i < scene.detectors.size(); ++i) {
        const double reach = extremes.reach;
        extremes.add(scene.detectors[i]);
        note(reach, [i] { return jsonpath::element("detectors", i); });
    }
    if (extremes.withinLimit()) return;
    const ShapePlace place = shapePlace(scene, finest);
    throw SceneError(scene.origin, place.path,
                     place.what + ": " + scaleLimitMessage(extremes.feature, extremes.reach, scene.unit, reachPlace()));
}

}  // namespace dropscope
