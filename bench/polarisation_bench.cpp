// What carrying Stokes vectors costs: photons per second of the same runs traced with
// --polarisation stokes and with none (the unpolarised Fresnel reflectance), interleaved in one process,
// on one thread, on three scenes: a lone water sphere (few interfaces per photon, so the Stokes work is
// the largest share), the default scene (a glass cell and drops) and a 1e5-droplet cloud (the octree
// search dominates). Both runs count what `dropscope trace` counts (the Stokes run also its Stokes
// columns). docs/performance.md ("Polarisation") has the figures and how to repeat them.
//
// Run: build/bench/polarisation_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]
#include "CloudScene.hpp"
#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "run/TraceRun.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/FateTally.hpp"
#include "tally/StandardTallies.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using dropscope::bench::cloudSceneText;
using dropscope::bench::fixed;
using dropscope::bench::median;
using dropscope::bench::parseCount;

struct Options {
    std::uint64_t photons = 200000;      // per run, lone sphere and default scene
    std::uint64_t cloudPhotons = 50000;  // per run, the cloud (slower photons: about 8.5 interfaces each)
    int repeat = 7;
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout << "polarisation_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7 (median of)]\n";
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        if (flag == "--photons")
            options.photons = parseCount(flag, value);
        else if (flag == "--cloud-photons")
            options.cloudPhotons = parseCount(flag, value);
        else if (flag == "--repeat")
            options.repeat = std::max(1, static_cast<int>(parseCount(flag, value)));
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    return options;
}

struct Row {
    std::string scene;
    std::uint64_t photons = 0;
    double interfacesPerPhoton = 0.0;
    std::vector<double> stokes, none;  // seconds of each run
};

double runSeconds(const OpticalScene& optical, const Scene& scene, std::uint64_t photons, PolarisationModel model,
                  double* interfacesPerPhoton = nullptr) {
    TraceSettings settings;
    settings.photons = photons;
    settings.threads = 1;
    settings.transport.polarisation = model;
    const TraceResult result = runTrace(optical, scene.sources, settings, standardTallies(180, model));
    if (interfacesPerPhoton) {
        const EventCounts& e = result.tallies.get<FateTally>().events();
        *interfacesPerPhoton = static_cast<double>(e.reflect + e.refract + e.tir) / static_cast<double>(photons);
    }
    return result.seconds;
}

// The two models alternate, so both see the same drift in the machine's load.
Row measure(const std::string& name, const Scene& scene, std::uint64_t photons, int repeat) {
    std::cerr << name << '\n';
    const OpticalScene optical(scene);
    Row row{name, photons, 0.0, {}, {}};
    runSeconds(optical, scene, std::min<std::uint64_t>(photons, 2000), PolarisationModel::Stokes);  // warm-up
    for (int r = 0; r < repeat; ++r) {
        row.stokes.push_back(runSeconds(optical, scene, photons, PolarisationModel::Stokes, &row.interfacesPerPhoton));
        row.none.push_back(runSeconds(optical, scene, photons, PolarisationModel::None));
    }
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        const std::string source = DROPSCOPE_SOURCE_DIR;
        std::vector<Row> rows;
        rows.push_back(measure("lone water sphere (validation/rainbow.json)",
                               loadScene(source + "/assets/scenes/validation/rainbow.json"), options.photons,
                               options.repeat));
        rows.push_back(measure("default scene (assets/scenes/default.json)",
                               loadScene(source + "/assets/scenes/default.json"), options.photons, options.repeat));
        rows.push_back(measure("cloud of 1e5 droplets (bench/CloudScene.hpp)",
                               parseScene(cloudSceneText(100000, 15.0), "cloud"), options.cloudPhotons,
                               options.repeat));
        std::cout << "polarisation_bench: one thread, median of " << options.repeat << " runs per model\n\n"
                  << "| scene | photons per run | interfaces per photon | stokes photons/s | none photons/s | "
                     "time stokes / none |\n|---|---|---|---|---|---|\n";
        for (const Row& row : rows) {
            const double stokes = median(row.stokes), none = median(row.none);
            const auto photons = static_cast<double>(row.photons);
            std::cout << "| " << row.scene << " | " << row.photons << " | " << fixed(row.interfacesPerPhoton, 2)
                      << " | " << fixed(photons / stokes, 0) << " | " << fixed(photons / none, 0) << " | "
                      << fixed(stokes / none, 3) << " |\n";
        }
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "polarisation_bench: " << error.what() << '\n';
        return 2;
    }
}
