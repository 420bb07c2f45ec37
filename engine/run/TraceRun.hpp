#pragma once

#include "scene/Source.hpp"
#include "tally/TallySet.hpp"
#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/PhotonTracer.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace dropscope {

struct TraceSettings {
    std::uint64_t photons = 0;
    // The run traces photons [firstPhoton, firstPhoton + photons): runs over consecutive ranges, their tallies
    // merged, are one run (the app traces in such batches to show results as they fill in).
    std::uint64_t firstPhoton = 0;
    std::uint64_t seed = 1;
    int threads = 0;          // 0: all the machine has (omp_get_max_threads)
    std::uint64_t paths = 0;  // record every event of photons [0, paths) (those of them this run traces)
    TransportSettings transport;
};

struct PhotonPath {
    std::uint64_t photon = 0;
    std::size_t source = 0;
    double wavelengthNm = 0.0;
    PhotonFate fate = PhotonFate::Lost;
    std::vector<Event> events;
};

struct TraceResult {
    std::uint64_t photons = 0;      // traced to the end (< requested only when stopped)
    TallySet tallies;               // the run's tallies, every photon traced scored into them
    std::vector<PhotonPath> paths;  // the recorded photons that were traced, by photon index
    std::uint64_t requested = 0;
    bool partial = false;  // stopped before every requested photon was traced
    int threads = 1;       // in each process
    int ranks = 1;         // processes the run was split across (MPI, docs/scaling.md)
    double seconds = 0.0;
};

struct TraceProgress {
    std::uint64_t done;
    std::uint64_t total;
    double seconds;
};

// Optional hooks of a long run. onProgress is called from one thread, about every `interval`
// seconds; when *stop becomes true no new photons are started and the result is marked partial.
struct TraceControl {
    std::function<void(const TraceProgress&)> onProgress;
    const std::atomic<bool>* stop = nullptr;
    double interval = 0.25;
};

// Traces settings.photons photons and scores each into `tallies` (unscored tallies: their bins and
// filters; standardTallies is what `dropscope trace` counts). Photon i comes from
// sources[i % sources.size()] with the random numbers PhotonRandom(seed, i). Each thread scores into
// its own emptyCopy() of the tallies, merged at the end; tallies merge exactly (tally/Tally.hpp), so
// the result is the same for any thread count. Its wavelength and, in a divergent beam, its direction come
// from PhotonRandom(seed, i, kSourceStream) (emitLight). Throws std::invalid_argument when there are no
// sources, for a source whose polarisation checkPolarisation or divergence checkDivergence refuses, for a
// medium that is not defined at a wavelength a source emits (findWavelengthCoverageProblem), or for
// PolarisationModel::Stokes with Schlick's approximation.
TraceResult runTrace(const OpticalScene& scene, const std::vector<Source>& sources, const TraceSettings& settings,
                     const TallySet& tallies, const TraceControl& control = {});

}  // namespace dropscope
