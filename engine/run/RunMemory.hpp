#pragma once

#include "run/TraceRun.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace dropscope {

// What a trace will allocate beyond the scene (docs/limits.md, "Memory"), in one process: a copy of the
// tallies per thread, the prepared (empty) set and the merged one, the recorded paths, and the detectors'
// records (each thread keeps its own first ones).
struct TraceMemory {
    double tallyBytes = 0.0;  // one copy of the tallies
    int threads = 1;
    double pathBytes = 0.0;
    double recordBytes = 0.0;
    double total() const { return tallyBytes * (threads + 2) + pathBytes + recordBytes; }
};

// Bytes a recorded path is estimated at: room for 16 events (a vector grown by doubling past 8 to 15 events,
// what a photon through a few droplets has), more than most photons of droplet scenes need (docs/limits.md).
inline constexpr double kPathBytesEstimate = sizeof(PhotonPath) + 16 * sizeof(Event);

// `records`: the sum of the detectors' "record" counts.
TraceMemory estimateTraceMemory(const TallySet& tallies, const TraceSettings& settings, std::uint64_t records);

// "this trace needs about 34 GB (tallies 16 GB per thread x 2 threads and the merged copy, paths 1 GB,
// detector records 0 bytes), more than the 8 GB this machine has available (docs/limits.md)", or nothing.
std::optional<std::string> traceMemoryProblem(const TraceMemory& need, double availableBytes);

}  // namespace dropscope
