// What carrying Stokes vectors costs: photons per second of the same runs traced with
// --polarisation stokes and with none (the unpolarised Fresnel reflectance), interleaved in one process,
// on one thread, on three scenes: a lone water sphere (few interfaces per photon, so the Stokes work is
// the largest share), the default scene (a glass cell and drops) and a 1e5-droplet cloud (the octree
// search dominates). Both runs count what `dropscope trace` counts (the Stokes run also its Stokes
// columns). docs/performance.md ("Polarisation") has the figures and how to repeat them.
//
// Run: build/bench/polarisation_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]
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

bench::PairedRow measure(const std::string& name, const Scene& scene, std::uint64_t photons, int repeat) {
    const OpticalScene optical(scene);
    const auto run = [&](PolarisationModel model) {
        return [&, model](std::uint64_t count) {
            TraceSettings settings;
            settings.photons = count;
            settings.threads = 1;
            settings.transport.polarisation = model;
            return runTrace(optical, scene.sources, settings, standardTallies(180, model));
        };
    };
    return measurePair(name, photons, repeat, run(PolarisationModel::Stokes), run(PolarisationModel::None));
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const PairedOptions options =
            parsePairedOptions(argc, argv, "polarisation_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]");
        const std::string source = DROPSCOPE_SOURCE_DIR;
        std::vector<PairedRow> rows;
        rows.push_back(measure("lone water sphere (validation/rainbow.json)",
                               loadScene(source + "/assets/scenes/validation/rainbow.json"), options.photons,
                               options.repeat));
        rows.push_back(measure("default scene (assets/scenes/default.json)",
                               loadScene(source + "/assets/scenes/default.json"), options.photons, options.repeat));
        rows.push_back(measure("cloud of 1e5 droplets (bench/CloudScene.hpp)",
                               parseScene(cloudSceneText(100000, 15.0), "cloud"), options.cloudPhotons,
                               options.repeat));
        printPairedTable("polarisation_bench", "stokes", "none", options.repeat, rows);
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "polarisation_bench: " << error.what() << '\n';
        return 2;
    }
}
