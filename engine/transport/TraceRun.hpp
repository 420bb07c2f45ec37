#pragma once

#include "scene/Source.hpp"
#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/PhotonTracer.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace dropscope {

struct TraceSettings {
    std::uint64_t photons = 0;
    std::uint64_t seed = 1;
    int bins = 180;           // angular bins over 0-180 degrees
    int threads = 0;          // 0: all the machine has (omp_get_max_threads)
    std::uint64_t paths = 0;  // record every event of photons [0, paths)
    TransportSettings transport;
};

// What the photons of a run came to. Only integer counts, so merging the tallies of any number of
// threads in any order gives the same numbers.
struct TraceTally {
    std::uint64_t photons = 0;  // traced to the end
    std::uint64_t escaped = 0;
    std::uint64_t absorbed = 0;
    std::uint64_t lost = 0;
    std::uint64_t unscattered = 0;  // escaped without meeting any surface
    EventCounts events;
    std::array<std::uint64_t, kLostReasonCount> lostReasons{};
    std::vector<std::uint64_t> angular;  // escapes per bin of the angle to the emission direction

    explicit TraceTally(int bins = 0) : angular(static_cast<std::size_t>(bins), 0) {}
    void add(const PhotonOutcome& outcome, const Direction& emitted);
    TraceTally& operator+=(const TraceTally& other);
};

struct PhotonPath {
    std::uint64_t photon = 0;
    std::size_t source = 0;
    PhotonFate fate = PhotonFate::Lost;
    std::vector<Event> events;
};

struct TraceResult {
    TraceTally tally;
    std::vector<PhotonPath> paths;  // the recorded photons that were traced, by photon index
    std::uint64_t requested = 0;
    bool partial = false;  // stopped before every requested photon was traced
    int threads = 1;
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

// Photon i comes from sources[i % sources.size()] with the random numbers PhotonRandom(seed, i).
// Throws std::invalid_argument when there are no sources or bins < 1.
TraceResult runTrace(const OpticalScene& scene, const std::vector<Source>& sources, const TraceSettings& settings,
                     const TraceControl& control = {});

}  // namespace dropscope
