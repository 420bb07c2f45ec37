#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

namespace CLI {
class App;
}

namespace dropscope {

struct TraceOptions {
    std::string scenePath;
    std::uint64_t photons = 0;
    std::uint64_t seed = 1;
    int bins = 180;
    int threads = 0;  // 0: all
    std::uint64_t paths = 0;
    std::uint32_t maxEvents = 10000;
    std::string fresnel = "exact";
    std::string polarisation;          // "stokes" | "none"; empty: stokes, or none with --fresnel schlick
    std::string diffraction = "none";  // --diffraction none|fraunhofer
    int wavelengthBins = 1;
    bool orders = false;
    std::string outDir;
};

// Registers `dropscope trace SCENE --photons N [--seed S] [--bins B] [--threads T] [--paths K]
// [--max-events M] [--fresnel exact|schlick] [--polarisation stokes|none] [--wavelength-bins K] [--diffraction
// none|fraunhofer] [--orders]
// --out DIR`.
CLI::App* addTraceCommand(CLI::App& app, TraceOptions& options);

// Traces the photons (engine/transport runTrace) and writes DIR/summary.json, the tables as CSV (angular.csv,
// angular_spectral.csv, angular_orders.csv with --orders, one or two per detector), far-field images as PNG and
// DIR/paths.jsonl (docs/cli.md), all whole or none; a short summary goes to `out`, a progress
// line to `err` when that is a terminal. Ctrl-C stops the run: the partial results are written and
// the status is kExitInterrupted. Bad input (scene, output directory) throws SceneError or
// BadInputError, which runCli reports, before any file is written. (Not `runTrace`: that is the
// engine's function this one calls.)
int runTraceCommand(const TraceOptions& options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
