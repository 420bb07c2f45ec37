#pragma once

#include "scene/Scene.hpp"
#include "wave/Mie.hpp"

#include <complex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace dropscope {

// The relative index (n + i kappa) / n_ambient of `medium` in the scene's ambient at the scene wavelength (kappa
// from the medium's absorption, sigma lambda / 4 pi). Throws std::invalid_argument when the ambient absorbs:
// Lorenz-Mie theory here is for a clear host.
std::complex<double> relativeIndexInScene(const Scene& scene, const Medium& medium);

// 2 pi n_ambient / lambda per scene unit: a sphere of radius r has size parameter x = r times this.
double sceneWavenumber(const Scene& scene);

// What Lorenz-Mie theory says about a scene whose shapes are all spheres of one medium, in the ambient: one sphere
// or a cloud (the app's Results panel compares its traces with it).
struct SphereSceneMie {
    std::complex<double> m;
    std::vector<double> sizes;  // every droplet's size parameter, ascending (one when they are all equal)
    std::size_t spheres = 0;
    std::string medium;
};

// The scene's spheres, or a sentence saying why the scene is not one sphere or a cloud of spheres Mie theory can
// compute (another shape, two media, an absorbing ambient, x outside 1e-3..2e4).
std::variant<SphereSceneMie, std::string> sphereSceneMie(const Scene& scene);

// `count` of the ascending `sizes` at probability midpoints, standing for them all in an average (all of them when
// there are no more than `count`).
std::vector<double> sizeSample(const std::vector<double>& sizes, std::size_t count);

}  // namespace dropscope
