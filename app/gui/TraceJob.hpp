#pragma once

#include "run/TraceRun.hpp"
#include "scene/Scene.hpp"
#include "tally/SpectralAngularTally.hpp"
#include "wave/SceneMie.hpp"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace dropscope::gui {

// What a finished run hands back: the result, the scene it traced (media names, the path inspector) and,
// when the worker failed (a scene without sources, ...), the error's message instead of a result.
struct TraceOutcome {
    TraceResult result;
    Scene scene;
    std::optional<std::string> error;
    // Lorenz-Mie theory of the scene's spheres when it is one sphere or a cloud of spheres (sphereSceneMie, in the
    // angular bins of the trace), computed beside the trace; otherwise why not, in `mieNote`.
    std::optional<SphereSceneMie> mieSpheres = std::nullopt;
    std::optional<MieResult> mie = std::nullopt;
    std::string mieNote = {};
};

// How far the current run is. Named apart from the engine's TraceProgress, which it extends with the
// phase. Each field is read on its own, so they may come from two neighbouring reports.
struct TraceJobProgress {
    bool buildingOctree = false;  // the octree is being built; no photon has started yet
    std::uint64_t done = 0;       // photons traced to the end
    std::uint64_t total = 0;      // photons requested
    double seconds = 0.0;         // since the photons started
};

// The tallies of the photons traced so far while a run goes on (its batches merged; see TraceJob).
struct TracePartial {
    TallySet tallies;
    std::uint64_t photons = 0;    // traced so far
    std::uint64_t requested = 0;  // in the whole run
};

// A trace run on a worker thread for the GUI, which keeps drawing while it goes: builds the scene's
// OpticalScene and calls runTrace with a stop flag and a progress hook, in batches of consecutive photons
// (TraceSettings::firstPhoton) whose tallies merge exactly: the outcome is the same as one runTrace's, and after
// each batch the tallies so far are offered to the UI (takePartial). A batch lasts about kBatchSeconds.
//
// Every member function is called from the UI thread only. The worker touches its own scene and result
// and the atomics; its outcome passes to the UI thread through join(), which orders the two, and its partial
// tallies through partial_, under partialMutex_.
//
// Stopping is not instant: runTrace checks the stop flag between chunks of 256 photons per thread, so a
// cancelled run ends once each thread finishes its chunk, and the octree is built before the first
// check. start() and the destructor wait that long; cancel() does not wait. Measured on 2 busy cores
// (tests/gui/TraceJobTest.cpp prints them): 2-20 ms on assets/scenes/cloud.json, whose octree of
// 20,000 droplets takes 55-85 ms to build. The worst case is 256 photons all trapped until the event
// cap (10,000 events each, in a glass cube): 0.3-0.6 s a chunk on one thread, and the run ended
// 0.6-1.2 s after cancel(). It grows with TransportSettings::maxEvents. A run also waits for the Mie theory it
// computes beside the photons (TraceOutcome::mie), which is kept to about half a second (TraceJob.cpp).
class TraceJob {
public:
    TraceJob() = default;
    ~TraceJob();  // cancels a run still going and waits for it
    TraceJob(const TraceJob&) = delete;
    TraceJob& operator=(const TraceJob&) = delete;

    // Starts tracing `scene` into standardTallies (180 angular bins; with `wavelengths`, the angular
    // distribution per band too), an OrderTally of the same bins and the scene's detector tallies
    // (addDetectorTallies: one per detector and the BudgetTally). A run still going is cancelled and waited for first,
    // and its result (or a finished one not yet taken) is dropped: only the new run's outcome is delivered.
    void start(Scene scene, TraceSettings settings, std::optional<WavelengthBins> wavelengths = std::nullopt);
    // Asks the run to stop; it ends soon after (see above) with a partial result. Returns at once.
    void cancel();
    // Whether a run has started and not yet finished.
    bool running() const;
    TraceJobProgress progress() const;
    // Cancels a run still going, waits for it and drops its outcome: nothing from before is delivered
    // (opening another scene).
    void discard();
    // The outcome of the finished run, once; nothing while it is running or when already taken.
    std::optional<TraceOutcome> takeResult();
    // The tallies so far of the run going on, once per batch finished; nothing before the first, when already
    // taken, or once the run has finished (its outcome has them all).
    std::optional<TracePartial> takePartial();

private:
    void run(Scene scene, const TraceSettings& settings, const std::optional<WavelengthBins>& wavelengths);
    void joinWorker();
    // The Mie theory of the scene's spheres, computed once for the same spheres (live traces of an unchanged
    // droplet set reuse it). Touched by the worker only, one at a time.
    void solveMie(const Scene& scene, TraceOutcome& outcome);

    std::thread worker_;
    std::optional<TraceOutcome> outcome_;  // written by the worker, read after joining it
    std::mutex partialMutex_;              // guards partial_, which the worker and the UI thread both touch
    std::optional<TracePartial> partial_;
    std::atomic<bool> stop_{false};
    std::atomic<bool> finished_{false};
    std::atomic<bool> buildingOctree_{false};
    std::atomic<std::uint64_t> done_{0};
    std::atomic<std::uint64_t> total_{0};
    std::atomic<double> seconds_{0.0};
    std::optional<std::pair<SphereSceneMie, MieResult>> mieCache_;
};

}  // namespace dropscope::gui
