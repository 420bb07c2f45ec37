// What wavelengths cost: photons per second of the same scenes traced with the sun's spectrum and with one
// line at the scene wavelength, interleaved in one process, on one thread. The water is the built-in
// (IAPWS index, Hale and Querry absorption) in both runs: the line's photons use the media's numbers at the
// scene wavelength, computed once; each of the sun's photons samples its wavelength and evaluates every
// medium at it. Scenes: a lone water drop (few interfaces per photon: the per-photon work is the largest
// share) and a 1e5-droplet cloud (the octree search dominates). docs/performance.md ("Wavelengths").
//
// Run: build/bench/spectral_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]
#include "CloudScene.hpp"
#include "PairedRuns.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/StandardTallies.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using namespace dropscope::bench;

// The water of `text` made the built-in water (n and kappa).
Scene withBuiltinWater(const std::string& text) {
    std::string builtin = text;
    const std::string constant = R"("water": {"n": 1.3337, "kappa": 1.9e-9})";
    const std::size_t at = builtin.find(constant);
    if (at == std::string::npos) throw std::logic_error("the cloud's water is not where it was");
    builtin.replace(at, constant.size(), R"("water": {"n": {"builtin": "water"}, "kappa": {"builtin": "water"}})");
    return parseScene(builtin, "scene");
}

const char* kDrop = R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
  "media": {"air": {"n": 1.000278}, "water": {"n": 1.3337, "kappa": 1.9e-9}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1}]})";

PairedRow measure(const std::string& name, const Scene& scene, std::uint64_t photons, int repeat) {
    const OpticalScene optical(scene);
    std::vector<Source> sun = scene.sources;
    for (Source& source : sun) source.spectrum = Spectrum::sun();
    const auto run = [&](const std::vector<Source>& sources) {
        return [&](std::uint64_t count) {
            TraceSettings settings;
            settings.photons = count;
            settings.threads = 1;
            return runTrace(optical, sources, settings, standardTallies(180, settings.transport.polarisation));
        };
    };
    return measurePair(name, photons, repeat, run(sun), run(scene.sources));
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const PairedOptions options =
            parsePairedOptions(argc, argv, "spectral_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]");
        std::vector<PairedRow> rows;
        rows.push_back(
            measure("lone water drop, built-in water", withBuiltinWater(kDrop), options.photons, options.repeat));
        rows.push_back(measure("cloud of 1e5 droplets, built-in water (bench/CloudScene.hpp)",
                               withBuiltinWater(cloudSceneText(100000, 15.0)), options.cloudPhotons, options.repeat));
        printPairedTable("spectral_bench", "sun", "line", options.repeat, rows);
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "spectral_bench: " << error.what() << '\n';
        return 2;
    }
}
