#pragma once

#include "run/TraceRun.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace dropscope {

// What a trace will allocate beyond the scene (docs/limits.md, "Memory"), in one process: a copy of the
// tallies per thread, the prepared (empty) set and the merged one, the recorded paths, and the detectors'
// records (each thread keeps its own first ones). Under MPI, rank 0 also holds one other rank's result at a
// time while merging, as bytes and as tallies: two more tally copies and records, and its paths as bytes.
struct TraceMemory {
    double tallyBytes = 0.0;  // one copy of the tallies
    int threads = 1;
    double pathBytes = 0.0;
    double recordBytes = 0.0;  // every copy: threads + 1 of them
    bool mergesRanks = false;
    int tallyCopies() const { return threads + (mergesRanks ? 4 : 2); }
    double pathTotal() const { return mergesRanks ? 2.0 * pathBytes : pathBytes; }
    double recordTotal() const { return recordBytes + (mergesRanks ? 2.0 * recordBytes / (threads + 1) : 0.0); }
    double total() const { return tallyBytes * tallyCopies() + pathTotal() + recordTotal(); }
};

// Bytes a recorded path is estimated at: room for 16 events (a vector grown by doubling past 8 to 15 events,
// what a photon through a few droplets has), more than most photons of droplet scenes need (docs/limits.md).
inline constexpr double kPathBytesEstimate = sizeof(PhotonPath) + 16 * sizeof(Event);

// `records`: the sum of the detectors' "record" counts; `ranks`: the MPI ranks of the run.
TraceMemory estimateTraceMemory(const TallySet& tallies, const TraceSettings& settings, std::uint64_t records,
                                int ranks = 1);

// "this trace needs about 65 GB (tallies 16 GB per thread x 2 threads and two more copies, paths 1 GB,
// detector records 0 bytes), more than the 8 GB this machine has available (docs/limits.md)", or nothing.
std::optional<std::string> traceMemoryProblem(const TraceMemory& need, double availableBytes);

}  // namespace dropscope
