#pragma once

#include "run/TraceRun.hpp"
#include "scene/Scene.hpp"
#include "tally/TallySet.hpp"

#include <cstdint>
#include <iosfwd>
#include <optional>
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
    std::optional<double> maxLost;  // --max-lost F: exit kExitTooManyLost when the lost share is above F
    std::string outDir;
};

// The bounds of trace's options, shared with the Python module.
inline constexpr std::uint64_t kMaxTraceBins = 100'000;      // 0.0018 degrees; a tally per thread: 0.8 MB each
inline constexpr std::uint64_t kMaxTraceThreads = 1024;      // beyond any machine we run on; a typo otherwise
inline constexpr std::uint64_t kMaxTracePaths = 1'000'000;   // every event kept in memory: ~1 KB per photon
inline constexpr std::uint64_t kMaxWavelengthBins = 10'000;  // angular_spectral.csv's bands
// Bins of angular_spectral.csv: K wavelength bands times --bins angles, a tally per thread of up to
// kMaxTraceBins * kMaxWavelengthBins counters would not fit, so the product is bounded too.
inline constexpr std::uint64_t kMaxSpectralCells = 10'000'000;  // 80 MB of counters per thread at most

// What a trace of `scene` with these options runs: the settings and the unscored tallies (standard, orders,
// detectors), checked. The CLI and the Python module both trace through it, so the same options give the same
// files. `ranks`: the MPI ranks of the run, for the memory estimate (rank 0 merges their results). Throws
// BadInputError (options) or SceneError (a scene without sources).
struct PreparedTrace {
    TraceSettings settings;
    TallySet tallies;
};
PreparedTrace prepareTrace(const TraceOptions& options, const Scene& scene, int ranks = 1);
// The settings alone, with the checks that need no scene (BadInputError): what trace refuses before reading it.
TraceSettings checkedTraceSettings(const TraceOptions& options);

// Registers `dropscope trace SCENE --photons N [--seed S] [--bins B] [--threads T] [--paths K]
// [--max-events M] [--fresnel exact|schlick] [--polarisation stokes|none] [--wavelength-bins K] [--diffraction
// none|fraunhofer] [--orders] [--max-lost F]
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
