#include "cli/TraceCommand.hpp"

#include "cli/BadInput.hpp"
#include "cli/Cli.hpp"
#include "cli/InterruptGuard.hpp"
#include "cli/OutputDirectory.hpp"
#include "cli/ProgressLine.hpp"
#include "cli/RankTrace.hpp"
#include "cli/Ranks.hpp"
#include "cli/WholeNumberOption.hpp"
#include "results/TraceFiles.hpp"
#include "run/TraceRun.hpp"
#include "scene/JsonDocument.hpp"
#include "scene/SceneLimits.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/FateTally.hpp"
#include "tally/OrderTally.hpp"
#include "tally/StandardTallies.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <new>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

namespace dropscope {

namespace {

namespace fs = std::filesystem;

std::string listed(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

void printSummary(const TraceResult& result, const fs::path& directory, std::ostream& out) {
    const FateTally& fates = result.tallies.get<FateTally>();
    const double photons = static_cast<double>(result.photons);
    const auto share = [&](std::uint64_t count) { return photons > 0.0 ? static_cast<double>(count) / photons : 0.0; };
    char line[320];
    if (result.partial) {
        std::snprintf(line, sizeof line, "trace: interrupted after %llu of %llu photons",
                      static_cast<unsigned long long>(result.photons),
                      static_cast<unsigned long long>(result.requested));
    } else {
        std::snprintf(line, sizeof line, "trace: %llu photons", static_cast<unsigned long long>(result.photons));
    }
    out << line;
    std::snprintf(line, sizeof line, " in %.3f s (%.0f photons/s, %d threads", result.seconds,
                  result.seconds > 0.0 ? photons / result.seconds : 0.0, result.threads);
    out << line;
    if (result.ranks > 1) {
        std::snprintf(line, sizeof line, " in each of %d ranks", result.ranks);
        out << line;
    }
    std::snprintf(line, sizeof line, ")\n");
    out << line;
    std::snprintf(line, sizeof line, "  escaped %.6g (unscattered %.6g), absorbed %.6g, lost %.6g\n",
                  share(fates.escaped()), share(fates.unscattered()), share(fates.absorbed()), share(fates.lost()));
    out << line;
    out << "  wrote " << listed(traceFileNames(result.tallies)) << (result.partial ? " (partial results)" : "")
        << " in " << directory.string() << '\n';
}

}  // namespace

CLI::App* addTraceCommand(CLI::App& app, TraceOptions& options) {
    CLI::App* command =
        app.add_subcommand("trace", "Trace photons through a scene: fates, angular distribution, paths");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_option("--photons", options.photons, "Photons to trace (1e6 style accepted)")
        ->required()
        ->transform(wholeNumberIn(1, kNoUpperBound));
    command->add_option("--seed", options.seed, "Seed: photon i uses the random stream (seed, i)")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kNoUpperBound));
    command->add_option("--bins", options.bins, "Angular bins over 0-180 degrees in angular.csv")
        ->capture_default_str()
        ->transform(wholeNumberIn(1, kMaxTraceBins));
    command->add_option("--threads", options.threads, "Threads; 0: all the machine has")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kMaxTraceThreads));
    command->add_option("--paths", options.paths, "Record every event of the first K photons in paths.jsonl")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kMaxTracePaths));
    command->add_option("--max-events", options.maxEvents, "Surface events before a photon is counted lost")
        ->capture_default_str()
        ->transform(wholeNumberIn(1, std::numeric_limits<std::uint32_t>::max()));
    command->add_option("--fresnel", options.fresnel, "Reflectance: exact Fresnel equations or Schlick's approximation")
        ->capture_default_str()
        ->check(CLI::IsMember({"exact", "schlick"}));
    command
        ->add_option("--polarisation", options.polarisation,
                     "stokes: Stokes vectors through every interface, Stokes columns in angular.csv; none: unpolarised "
                     "Fresnel reflectance, as before polarisation (the default with --fresnel schlick)")
        ->default_str("stokes; none with --fresnel schlick")
        ->check(CLI::IsMember({"stokes", "none"}));
    command
        ->add_option("--wavelength-bins", options.wavelengthBins,
                     "Equal wavelength bins over the sources' spectra in angular_spectral.csv")
        ->capture_default_str()
        ->transform(wholeNumberIn(1, kMaxWavelengthBins));
    command
        ->add_option("--diffraction", options.diffraction,
                     "none: ray optics only; fraunhofer: half the photons that meet a sphere or an ellipsoid are "
                     "diffracted by its outline (Airy pattern) and pass it (docs/transport.md, \"Diffraction\")")
        ->capture_default_str()
        ->check(CLI::IsMember({"none", "fraunhofer"}));
    command
        ->add_option("--max-lost", options.maxLost,
                     "Exit with status 4, after writing every file, when the share of photons lost is above F (0 "
                     "to 1); a trace that loses any photon always warns on stderr")
        ->check(CLI::Range(0.0, 1.0));
    command->add_flag("--orders", options.orders,
                      "Ray orders: angular_orders.csv (p0 .. p5_plus of photons that met one shape, and multiple) and "
                      "single/multiple scattering shares in summary.json");
    command
        ->add_option("--out", options.outDir,
                     "Output folder (created): summary.json, angular.csv, angular_spectral.csv, detector files, "
                     "paths.jsonl")
        ->required();
    return command;
}

namespace {

// Everything a trace does before its photons, on every rank: the checks, the scene, the tallies. Only rank 0
// writes, so only it checks and creates the output folder.
struct TraceSetup {
    std::string sceneJson;
    Scene scene;
    PreparedTrace prepared;
    std::optional<OpticalScene> optical;
    bool createdOutput = false;  // --out did not exist before this run
};

void prepareTraceSetup(const TraceOptions& options, const Ranks& ranks, TraceSetup& setup) {
    const bool writes = ranks.root();
    const fs::path directory = options.outDir;
    const PolarisationModel polarisation = checkedTraceSettings(options).transport.polarisation;
    // The file names do not depend on the bins: checked before the scene is read.
    if (writes) {
        checkOutputDirectory(directory,
                             traceFileNames(standardTallies(options.bins, polarisation, WavelengthBins{1, 1.0, 1.0})));
    }
    // The text read once: results.h5 keeps exactly what was traced.
    setup.sceneJson = readJsonFileText(options.scenePath);
    setup.scene = parseScene(setup.sceneJson, options.scenePath);
    setup.prepared = prepareTrace(options, setup.scene, ranks.size());
    // The detectors' files are named after them: checked now that they are known.
    if (writes) checkOutputDirectory(directory, traceFileNames(setup.prepared.tallies));
    setup.optical.emplace(setup.scene, setup.prepared.settings.transport.diffraction != DiffractionModel::None);
}

// Until the run's files are written, a failure (an allocation, a full disk) leaves no sign of the run: the
// folder it created is removed again, which fs::remove does only when it is empty.
class FolderOfThisRun {
public:
    FolderOfThisRun(fs::path path, bool created) : path_(std::move(path)), created_(created) {}
    FolderOfThisRun(const FolderOfThisRun&) = delete;
    FolderOfThisRun& operator=(const FolderOfThisRun&) = delete;
    ~FolderOfThisRun() { discard(); }
    void keep() { kept_ = true; }
    // Now, for an exit that will not unwind (MPI_Abort).
    void discard() {
        std::error_code ignored;
        if (created_ && !kept_) fs::remove(path_, ignored);
    }

private:
    fs::path path_;
    bool created_;
    bool kept_ = false;
};

int traceAndWrite(const TraceOptions& options, const Ranks& ranks, std::ostream& out, std::ostream& err) {
    const fs::path directory = options.outDir;
    TraceSetup setup;
    ranks.together([&] { prepareTraceSetup(options, ranks, setup); });
    ranks.together([&] {
        if (!ranks.root()) return;
        std::error_code unknown;  // createOutputDirectory reports a path that cannot be used
        setup.createdOutput = !fs::exists(directory, unknown);
        createOutputDirectory(directory);
    });
    const Scene& scene = setup.scene;
    const TraceSettings& settings = setup.prepared.settings;
    FolderOfThisRun createdFolder(directory, setup.createdOutput);

    TraceRunInfo info{options.scenePath, scene.sources.size(), settings, scene.wavelengthNm, scene.sources};
    info.sceneJson = setup.sceneJson;
    info.maxLost = options.maxLost;
    // Alive until the files are written: a first Ctrl-C while writing them is absorbed, not fatal. mpirun
    // turns a Ctrl-C into SIGTERM to every rank, so a rank of an MPI run takes that as its Ctrl-C.
    const InterruptGuard interrupt(ranks.launched() ? InterruptGuard::kAlsoTerminate : InterruptGuard::kInterruptOnly);
    std::optional<ProgressLine> progress;
    if (ranks.root() && (isTerminal(err) || ranks.launched())) {
        // A rank's stderr is a pipe to mpirun, which may be a terminal or a batch job's log: whole lines.
        progress.emplace(err, ranks.launched() ? ProgressLine::Style::Lines : ProgressLine::Style::InPlace);
    }
    TraceControl control;
    control.stop = &interrupt.flag();
    if (progress) control.onProgress = [&](const TraceProgress& now) { progress->update(now); };
    TraceResult result;
    try {
        result = traceOnRanks(ranks, *setup.optical, scene.sources, info.settings, setup.prepared.tallies, control);
    } catch (const std::exception& error) {
        if (!ranks.parallel()) throw;
        // As for one process (exit 2 out of memory, 1 otherwise; nothing written), but every rank must end: the
        // others may be waiting for this one's messages. The folder rank 0 created stays when another rank
        // failed: MPI_Abort ends rank 0 without unwinding.
        const bool outOfMemory = dynamic_cast<const std::bad_alloc*>(&error) != nullptr;
        if (outOfMemory) {
            err << "dropscope: out of memory on rank " << ranks.rank()
                << ": this run needs more than the machine allows (docs/limits.md); nothing was written\n";
        } else {
            err << "dropscope: internal error on rank " << ranks.rank() << ": " << error.what() << '\n';
        }
        err.flush();
        createdFolder.discard();
        ranks.abort(outOfMemory ? kExitBadInput : kExitInternalError);
    }
    // Rank 0 owns the run's exit status: a rank that ended early with a status of its own could make mpirun
    // end the job while rank 0 still writes.
    if (!ranks.root()) return kExitSuccess;
    if (progress) progress->finish({result.photons, result.requested, result.seconds});
    result.tallies.get<FateTally>().nameShapes([&scene](ShapeId id) { return shapeLabel(scene, id); });

    try {
        writeTraceFiles(directory, result, info, setup.optical->media());
    } catch (const std::runtime_error& error) {
        throw BadInputError(error.what());
    }
    createdFolder.keep();
    printSummary(result, directory, out);
    out.flush();  // before MPI_Finalize: mpirun may end the job as soon as every rank has finished it
    const FateTally& fates = result.tallies.get<FateTally>();
    if (const auto warning = fates.lossWarning()) err << "dropscope: warning: " << *warning << '\n';
    if (result.partial) {
        err << "dropscope: trace interrupted: " << result.photons << " of " << result.requested
            << " photons traced, partial results in " << directory.string() << '\n';
        return kExitInterrupted;
    }
    const double lostShare =
        fates.photons() > 0 ? static_cast<double>(fates.lost()) / static_cast<double>(fates.photons()) : 0.0;
    if (options.maxLost && lostShare > *options.maxLost) {
        char line[160];
        std::snprintf(line, sizeof line, "dropscope: lost share %.6g is above --max-lost %.6g (results written)\n",
                      lostShare, *options.maxLost);
        err << line;
        return kExitTooManyLost;
    }
    return kExitSuccess;
}

}  // namespace

int runTraceCommand(const TraceOptions& options, std::ostream& out, std::ostream& err) {
    const Ranks ranks;
    try {
        return traceAndWrite(options, ranks, out, err);
    } catch (const RankFailed& failed) {
        return failed.status;  // the lower rank that failed has said why
    } catch (const std::exception&) {
        if (!ranks.parallel()) throw;
        // Said before ~Ranks (MPI_Finalize) lets the other ranks exit: mpirun ends the job at their first exit
        // status that is not 0, and this rank's message would be lost with it.
        const int status = reportFailure(std::current_exception(), err);
        err.flush();
        return status;
    }
}

}  // namespace dropscope
