// What a trace runs, from its options and scene: shared by `dropscope trace` and the Python module, in a file of
// its own so that the module does not link the command (and MPI with it).
#include "cli/BadInput.hpp"
#include "cli/TraceCommand.hpp"
#include "run/RunMemory.hpp"
#include "scene/MachineMemory.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/OrderTally.hpp"
#include "tally/StandardTallies.hpp"

#include <cmath>
#include <string>

namespace dropscope {

namespace {

// --polarisation, default stokes; Schlick's approximation is unpolarised, so with --fresnel schlick the
// default is none and an explicit stokes is refused.
PolarisationModel polarisationModel(const TraceOptions& options) {
    const bool schlick = options.fresnel == "schlick";
    if (options.polarisation.empty()) return schlick ? PolarisationModel::None : PolarisationModel::Stokes;
    if (options.polarisation == "none") return PolarisationModel::None;
    if (schlick) {
        throw BadInputError("--polarisation stokes: needs --fresnel exact (Schlick's approximation is unpolarised)");
    }
    return PolarisationModel::Stokes;
}

TraceSettings traceSettings(const TraceOptions& options) {
    TraceSettings settings;
    settings.photons = options.photons;
    settings.seed = options.seed;
    settings.threads = options.threads;
    settings.paths = options.paths;
    settings.transport.maxEvents = options.maxEvents;
    settings.transport.fresnel = options.fresnel == "schlick" ? FresnelModel::Schlick : FresnelModel::Exact;
    settings.transport.polarisation = polarisationModel(options);
    settings.transport.diffraction =
        options.diffraction == "fraunhofer" ? DiffractionModel::Fraunhofer : DiffractionModel::None;
    return settings;
}

}  // namespace

TraceSettings checkedTraceSettings(const TraceOptions& options) {
    TraceSettings settings = traceSettings(options);  // refuses --polarisation stokes with Schlick first
    // CLI11's range check reads "nan" and lets it through; NaN would then never be exceeded.
    if (options.maxLost && !std::isfinite(*options.maxLost)) {
        throw BadInputError("--max-lost: must be a number from 0 to 1, not " + std::to_string(*options.maxLost));
    }
    if (static_cast<std::uint64_t>(options.bins) * static_cast<std::uint64_t>(options.wavelengthBins) >
        kMaxSpectralCells) {
        throw BadInputError("--bins " + std::to_string(options.bins) + " with --wavelength-bins " +
                            std::to_string(options.wavelengthBins) + ": more than " +
                            std::to_string(kMaxSpectralCells) + " cells in angular_spectral.csv");
    }
    return settings;
}

PreparedTrace prepareTrace(const TraceOptions& options, const Scene& scene, int ranks) {
    PreparedTrace prepared{checkedTraceSettings(options), {}};
    const TraceSettings& settings = prepared.settings;
    if (scene.sources.empty()) throw SceneError(scene.origin, "sources", "the scene has no light sources to trace");
    const auto [lo, hi] = wavelengthRangeNm(scene.sources, scene.wavelengthNm);
    const WavelengthBins wavelengths{options.wavelengthBins, lo, hi};
    try {
        wavelengths.check();
    } catch (const std::invalid_argument& error) {
        throw BadInputError("--wavelength-bins " + std::to_string(options.wavelengthBins) + ": " + error.what());
    }
    prepared.tallies = standardTallies(options.bins, settings.transport.polarisation, wavelengths);
    if (options.orders) {
        prepared.tallies.add(
            std::make_unique<OrderTally>(options.bins, settings.transport.diffraction != DiffractionModel::None));
    }
    addDetectorTallies(prepared.tallies, scene, settings.transport.polarisation);
    std::uint64_t records = 0;
    for (const Detector& detector : scene.detectors) records += detector.record;
    const TraceMemory need = estimateTraceMemory(prepared.tallies, settings, records, ranks);
    if (const auto problem = traceMemoryProblem(need, static_cast<double>(availableMemoryBytes()))) {
        throw BadInputError("dropscope: " + *problem +
                            "; use fewer --threads, --bins, --wavelength-bins, --paths, detector pixels or records");
    }
    return prepared;
}

}  // namespace dropscope
