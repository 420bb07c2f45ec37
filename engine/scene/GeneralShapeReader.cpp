#include "scene/GeneralShapeReader.hpp"

#include "geometry/implicit/Blob.hpp"
#include "geometry/implicit/ImplicitPresets.hpp"
#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "scene/JsonDocument.hpp"
#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/TransformReader.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace dropscope {

std::shared_ptr<const void> BaseCache::find(const std::string& key) const {
    const auto found = bases_.find(key);
    return found == bases_.end() ? nullptr : found->second;
}

void BaseCache::add(const std::string& key, std::shared_ptr<const void> base) { bases_.emplace(key, std::move(base)); }

namespace {

// The preset and every number it was built from, exactly (shortest round-trip form).
std::string cacheKey(std::string_view family, std::string_view preset, const std::vector<double>& numbers) {
    std::string key = std::string(family) + "/" + std::string(preset);
    char buffer[32];
    for (const double number : numbers) {
        const auto written = std::to_chars(buffer, buffer + sizeof buffer, number);
        key.append(" ").append(buffer, written.ptr);
    }
    return key;
}

template <class Base>
std::shared_ptr<const Base> cached(BaseCache& cache, const std::string& key,
                                   const std::function<std::shared_ptr<const Base>()>& make) {
    if (auto found = cache.find(key)) return std::static_pointer_cast<const Base>(found);
    std::shared_ptr<const Base> base = make();
    cache.add(key, base);
    return base;
}

std::vector<BezierNet> readPatchRow(const JsonReader& row) {
    std::vector<BezierNet> nets;
    for (const JsonReader& netJson : row.elements()) {
        const std::vector<JsonReader> netRows = netJson.elements();
        if (netRows.size() != 4)
            netJson.fail("must be 4 rows of 4 control points, got " + std::to_string(netRows.size()) + " rows");
        BezierNet net;
        for (std::size_t i = 0; i < 4; ++i) {
            const std::vector<JsonReader> points = netRows[i].elements();
            if (points.size() != 4) netRows[i].fail("must be 4 control points, got " + std::to_string(points.size()));
            for (std::size_t j = 0; j < 4; ++j) net[i][j] = points[j].vector3();
        }
        nets.push_back(net);
    }
    return nets;
}

std::vector<std::vector<BezierNet>> readPatches(const JsonReader& json) {
    std::vector<std::vector<BezierNet>> patches;
    for (const JsonReader& row : json.elements()) patches.push_back(readPatchRow(row));
    return patches;
}

// A file named relative to the scene file's folder, or failing that to the working directory.
std::filesystem::path resolveBeside(const JsonReader& json, const std::string& name) {
    const std::filesystem::path given(name);
    if (given.is_absolute()) return given;
    const std::filesystem::path beside = std::filesystem::path(json.origin()).parent_path() / given;
    std::error_code status;
    return std::filesystem::exists(beside, status) ? beside : given;
}

std::shared_ptr<const ParametricSurface> readBezier(const JsonReader& json) {
    const JsonReader patchesJson = json.member("patches");
    if (!patchesJson.isString()) {
        const auto patches = readPatches(patchesJson);
        return patchesJson.construct([&] { return makeBezierSurface(patches); });
    }
    const std::string name = patchesJson.string();
    if (name.empty()) patchesJson.fail("must be the patches or the name of a file holding them, not \"\"");
    const std::filesystem::path file = resolveBeside(patchesJson, name);
    // An error in the patches file names that file and its own path, after this value's place.
    try {
        return parseBezierPatchesFile(readJsonFileText(file), file.string());
    } catch (const SceneError& error) {
        patchesJson.fail(std::string("in the patches file: ") + error.what());
    }
}

std::shared_ptr<const ParametricSurface> readSurface(const JsonReader& json, const std::string& preset) {
    if (preset == "sphere") {
        json.expectKeys({"type", "preset", "radius", "transform", "medium", "name"});
        const JsonReader radius = json.member("radius");
        const double r = radius.positive();
        return radius.construct([&] { return makeSphereSurface(r); });
    }
    if (preset == "ellipsoid") {
        json.expectKeys({"type", "preset", "semi_axes", "transform", "medium", "name"});
        const JsonReader semiAxes = json.member("semi_axes");
        const Eigen::Vector3d axes = semiAxes.positiveVector3();
        return semiAxes.construct([&] { return makeEllipsoidSurface(axes); });
    }
    if (preset == "torus") {
        json.expectKeys({"type", "preset", "major_radius", "minor_radius", "transform", "medium", "name"});
        const double major = json.member("major_radius").positive();
        const JsonReader minorJson = json.member("minor_radius");
        const double minor = minorJson.positive();
        return minorJson.construct([&] { return makeTorusSurface(major, minor); });
    }
    if (preset == "bezier") {
        json.expectKeys({"type", "preset", "patches", "transform", "medium", "name"});
        return readBezier(json);
    }
    json.member("preset").fail("unknown parametric preset " + jsonpath::quoted(preset) +
                               " (known: sphere, ellipsoid, torus, bezier)");
}

std::vector<double> parameterNumbers(const std::vector<PresetParameter>& parameters) {
    std::vector<double> numbers;
    for (const PresetParameter& parameter : parameters)
        numbers.insert(numbers.end(), parameter.values.begin(), parameter.values.end());
    return numbers;
}

std::shared_ptr<const ImplicitFunction> readFunction(const JsonReader& json, const std::string& preset) {
    if (preset == "superellipsoid") {
        json.expectKeys({"type", "preset", "semi_axes", "exponents", "transform", "medium", "name"});
        const Eigen::Vector3d semiAxes = json.member("semi_axes").positiveVector3();
        const JsonReader exponentsJson = json.member("exponents");
        const std::vector<JsonReader> values = exponentsJson.elements();
        if (values.size() != 2)
            exponentsJson.fail("must be [e1, e2], got " + std::to_string(values.size()) + " numbers");
        const Eigen::Vector2d exponents(values[0].positive(), values[1].positive());
        return exponentsJson.construct([&] { return makeSuperellipsoid(semiAxes, exponents); });
    }
    if (preset == "blob") {
        json.expectKeys({"type", "preset", "centers", "radii", "blend", "transform", "medium", "name"});
        const std::vector<JsonReader> centerElements = json.member("centers").elements();
        if (centerElements.size() > kMaxBlobSpheres) {
            json.member("centers").fail("a blob has at most " + std::to_string(kMaxBlobSpheres) + " spheres, got " +
                                        std::to_string(centerElements.size()) +
                                        " (its load and trace time grow with the square of their number); model "
                                        "more droplets as separate shapes or a droplet cloud (docs/limits.md)");
        }
        std::vector<Point> centers;
        for (const JsonReader& center : centerElements) centers.push_back(center.vector3());
        const JsonReader radiiJson = json.member("radii");
        std::vector<double> radii;
        for (const JsonReader& radius : radiiJson.elements()) radii.push_back(radius.positive());
        if (radii.size() != centers.size()) {
            radiiJson.fail("must give one radius per center (" + std::to_string(centers.size()) + " centers, " +
                           std::to_string(radii.size()) + " radii)");
        }
        const double blend = json.member("blend").positive();
        return json.member("centers").construct([&] { return makeBlob(centers, radii, blend); });
    }
    json.member("preset").fail("unknown implicit preset " + jsonpath::quoted(preset) +
                               " (known: superellipsoid, blob)");
}

AffineTransform readOptionalTransform(const JsonReader& json) {
    const auto transform = json.optionalMember("transform");
    return transform ? readTransform(*transform) : AffineTransform();
}

// A `Placed` shape on the base made from `source` (once per preset and parameters: the cache), placed by
// the file's transform and checked usable.
template <class Placed, class Source, class MakeBase>
std::unique_ptr<Shape> placeOnBase(const JsonReader& json, BaseCache& cache, std::string_view family,
                                   const std::string& preset, const std::shared_ptr<const Source>& source,
                                   MakeBase makeBase) {
    const AffineTransform transform = readOptionalTransform(json);
    const std::string key = cacheKey(family, preset, parameterNumbers(source->presetParameters()));
    using Base = std::remove_const_t<typename decltype(makeBase(source))::element_type>;
    const auto base = cached<Base>(cache, key, [&] { return json.construct([&] { return makeBase(source); }); });
    return json.construct([&] {
        auto shape = std::make_unique<Placed>(base, transform);
        shape->checkUsable();
        return shape;
    });
}

}  // namespace

double implicitLoadSeconds(const ImplicitFunction& function) {
    if (const auto* blob = dynamic_cast<const Blob*>(&function)) {
        // Fitted to 0.59 s for 16 spheres and 3.1 s for 64; 0.14 s for 4.
        const auto spheres = static_cast<double>(blob->centers().size());
        return 0.033 * spheres + 0.00024 * spheres * spheres;
    }
    return 0.13;
}

void checkImplicitLoadTime(const JsonReader& shapes) {
    if (!shapes.isArray()) return;  // the shapes' reader says what is wrong
    std::set<std::string> bases;
    double seconds = 0.0;
    for (const JsonReader& json : shapes.elements()) {
        if (!json.isObject()) continue;
        const auto type = json.optionalMember("type");
        if (!type || !type->isString() || type->string() != "implicit") continue;
        // The function alone is cheap (its base integrates); a shape the reader refuses is left to it, to be
        // said in the file's order.
        std::shared_ptr<const ImplicitFunction> function;
        std::string preset;
        try {
            preset = json.member("preset").string();
            function = readFunction(json, preset);
        } catch (const SceneError&) {
            continue;
        }
        if (!bases.insert(cacheKey("implicit", preset, parameterNumbers(function->presetParameters()))).second)
            continue;
        seconds += implicitLoadSeconds(*function);
        if (seconds > kMaxImplicitLoadSeconds) {
            char text[64];
            std::snprintf(text, sizeof text, "about %.0f s to load, more than the limit of %.0f s", seconds,
                          kMaxImplicitLoadSeconds);
            json.fail("the scene's implicit shapes up to this one would take " + std::string(text) +
                      " (each distinct preset and parameters is integrated once: about 0.13 s for a "
                      "superellipsoid, 3.1 s for a blob of 64 spheres); shapes that differ only in transform "
                      "share one, so vary the transform's scale instead of the parameters (docs/limits.md)");
        }
    }
}

std::unique_ptr<Shape> readParametricShape(const JsonReader& json, BaseCache& cache) {
    const std::string preset = json.member("preset").string();
    return placeOnBase<ParametricShape>(json, cache, "parametric", preset, readSurface(json, preset),
                                        makeParametricBase);
}

std::unique_ptr<Shape> readImplicitShape(const JsonReader& json, BaseCache& cache) {
    const std::string preset = json.member("preset").string();
    return placeOnBase<ImplicitShape>(json, cache, "implicit", preset, readFunction(json, preset), makeImplicitBase);
}

std::shared_ptr<const ParametricSurface> parseBezierPatchesFile(std::string_view text, const std::string& origin) {
    const Json document = parseJsonDocument(text, origin);
    const JsonReader root(document, "", origin);
    root.expectObject();
    root.expectKeys({"patches"});
    const JsonReader filePatches = root.member("patches");
    const auto patches = readPatches(filePatches);
    return filePatches.construct([&] { return makeBezierSurface(patches); });
}

}  // namespace dropscope
