#pragma once

// The scenes of assets/scenes/validation traced in-process, once per process (CTest runs each test in
// its own, so the rainbow is traced once for each of its three tests; validate.sh runs one), and the figures
// the comparisons of docs/validation.md print.

#include "transport/RayOrderTally.hpp"
#include "transport/TallyExpectations.hpp"

#include "geometry/Sphere.hpp"
#include "scene/SceneLoader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>

namespace dropscope::validation {

// At most about 5 s of CPU per scene in the Release build, so the suite keeps to its CI budget, yet the
// secondary bow's bin stands 6 sigma above the next; DROPSCOPE_VALIDATION_PHOTONS (e.g. 1e8) overrides it.
constexpr std::uint64_t kDefaultPhotons = 10'000'000;
// Every statistical bound is this many binomial standard deviations: with fixed seeds a correct tracer
// never fails, and a shift of that size is caught.
constexpr double kSigmas = 5.0;

inline std::uint64_t validationPhotons() {
    const char* text = std::getenv("DROPSCOPE_VALIDATION_PHOTONS");
    if (text == nullptr || *text == '\0') return kDefaultPhotons;
    char* end = nullptr;
    const double photons = std::strtod(text, &end);
    if (*end != '\0' || !(photons >= 1e4 && photons <= 1e12) || photons != std::floor(photons)) {
        throw std::invalid_argument(
            std::string("DROPSCOPE_VALIDATION_PHOTONS must be a whole number from 1e4 to 1e12, not ") + text);
    }
    return static_cast<std::uint64_t>(photons);
}

// Ray orders 0 .. kLastRayOrder - 1 one by one in every run (RayOrderTally), the rest together.
constexpr int kLastRayOrder = 6;

// One validation scene: a sphere in the ambient medium, lit by a beam of the sphere's radius, so
// every photon meets it.
struct SphereScene {
    Scene scene;
    double n1 = 1.0;      // the ambient index
    double n2 = 1.0;      // the sphere's index
    double sigma = 0.0;   // the sphere's absorption coefficient, per scene unit
    double radius = 0.0;  // of the sphere
    double volume = 0.0;  // of the sphere
    double beamArea = 0.0;
    double relativeIndex() const { return n2 / n1; }
};

inline SphereScene loadSphereScene(const std::string& name) {
    SphereScene result{loadScene(std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/validation/" + name + ".json")};
    const Scene& scene = result.scene;
    const auto* sphere = scene.shapes.size() == 1 ? dynamic_cast<const Sphere*>(scene.shapes[0].get()) : nullptr;
    if (sphere == nullptr || scene.sources.size() != 1 || scene.sources[0].type != SourceType::Beam ||
        scene.sources[0].radius != sphere->radius()) {
        throw std::runtime_error(name + ": a validation scene is one sphere under one beam of the sphere's radius");
    }
    const Medium& water = scene.mediumOf(*sphere);
    result.n1 = scene.media[scene.ambient].n;
    result.n2 = water.n;
    result.sigma = water.absorptionPerUnit;
    result.radius = sphere->radius();
    result.volume = sphere->volume();
    result.beamArea = std::numbers::pi * scene.sources[0].radius * scene.sources[0].radius;
    return result;
}

// The run of a validation scene with `bins` angular bins, traced on first use (seed 1, all threads), with
// Stokes vectors (the default) or the unpolarised model.
inline const TraceResult& validationRun(const std::string& name, int bins,
                                        PolarisationModel polarisation = PolarisationModel::Stokes) {
    static std::map<std::tuple<std::string, int, PolarisationModel>, TraceResult> runs;
    const auto key = std::make_tuple(name, bins, polarisation);
    if (auto found = runs.find(key); found != runs.end()) return found->second;
    const SphereScene scene = loadSphereScene(name);
    TraceSettings settings;
    settings.photons = validationPhotons();
    settings.seed = 1;
    settings.transport.polarisation = polarisation;
    TallySet tallies = standardTallies(bins, polarisation);
    tallies.add(std::make_unique<test::RayOrderTally>(kLastRayOrder));
    TraceResult result = runTrace(OpticalScene(scene.scene), scene.scene.sources, settings, tallies);
    std::cout << "[validation] traced " << name << ".json (polarisation " << polarisationModelName(polarisation)
              << "): " << result.photons << " photons, " << result.threads << " threads, " << result.seconds << " s\n";
    return runs.emplace(key, std::move(result)).first->second;
}

inline std::string formatted(double value, const char* format = "%.6g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// A comparison's figures: test properties (in the XML/JSON report) and one stdout line.
inline void recordFigure(const std::string& name, const std::string& expected, const std::string& measured,
                         const std::string& bound, bool traced = true) {
    ::testing::Test::RecordProperty(name + "_expected", expected);
    ::testing::Test::RecordProperty(name + "_measured", measured);
    ::testing::Test::RecordProperty(name + "_bound", bound);
    std::cout << "[validation] " << name << ": expected " << expected << ", measured " << measured << " (" << bound;
    if (traced) std::cout << ", " << formatted(static_cast<double>(validationPhotons()), "%.3g") << " photons";
    std::cout << ")\n";
}

// One binomial standard deviation of a share p of n photons.
inline double binomialSigma(double p, double n) { return std::sqrt(p * (1.0 - p) / n); }

}  // namespace dropscope::validation
