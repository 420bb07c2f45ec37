#include "wave/SceneMie.hpp"

#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace dropscope {

std::complex<double> relativeIndexInScene(const Scene& scene, const Medium& medium) {
    const Medium& ambient = scene.media.at(scene.ambient);
    if (ambient.absorptionPerUnit > 0.0) {
        throw std::invalid_argument("the ambient medium \"" + ambient.name +
                                    "\" absorbs; Lorenz-Mie theory here needs a clear ambient");
    }
    const double kappa = medium.absorptionPerUnit * scene.wavelengthInSceneUnits() / (4.0 * std::numbers::pi);
    return std::complex<double>(medium.n, kappa) / ambient.n;
}

double sceneWavenumber(const Scene& scene) {
    return 2.0 * std::numbers::pi * scene.media.at(scene.ambient).n / scene.wavelengthInSceneUnits();
}

std::variant<SphereSceneMie, std::string> sphereSceneMie(const Scene& scene) {
    if (scene.shapes.empty()) return std::string("the scene has no shapes");
    SphereSceneMie result;
    const double wavenumber = sceneWavenumber(scene);
    std::optional<MediumId> medium;
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const Shape& shape = *scene.shapes[id];
        if (shape.kind() != ShapeKind::Sphere) {
            return "shape " + std::to_string(id) + " is a " + std::string(shape.typeName()) +
                   ": Mie theory is for spheres";
        }
        if (medium && *medium != shape.mediumId()) return std::string("the spheres are of different media");
        medium = shape.mediumId();
        result.sizes.push_back(wavenumber * static_cast<const Sphere&>(shape).radius());
    }
    result.spheres = result.sizes.size();
    const Medium& droplets = scene.media.at(*medium);
    result.medium = droplets.name;
    try {
        result.m = relativeIndexInScene(scene, droplets);
    } catch (const std::invalid_argument& error) {
        return std::string(error.what());
    }
    std::sort(result.sizes.begin(), result.sizes.end());
    const double smallest = result.sizes.front();
    const double largest = result.sizes.back();
    if (smallest < kMinSizeParameter || largest > kMaxSizeParameter) {
        return "size parameter x = " + jsonpath::number(smallest < kMinSizeParameter ? smallest : largest) +
               " is outside 1e-3..2e4";
    }
    if (smallest == largest) result.sizes.resize(1);
    return result;
}

std::vector<double> sizeSample(const std::vector<double>& sizes, std::size_t count) {
    if (sizes.size() <= count) return sizes;
    std::vector<double> sample(count);
    const auto all = static_cast<double>(sizes.size());
    for (std::size_t i = 0; i < count; ++i) {
        const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(count);
        sample[i] = sizes[static_cast<std::size_t>(p * all)];
    }
    return sample;
}

}  // namespace dropscope
