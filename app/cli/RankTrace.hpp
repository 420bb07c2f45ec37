#pragma once

#include "cli/Ranks.hpp"
#include "run/TraceRun.hpp"

namespace dropscope {

// The photons [first, first + count) of a run of `photons` that rank `rank` of `size` traces: consecutive
// shares that differ by at most one photon (N r / P to N (r + 1) / P).
struct PhotonShare {
    std::uint64_t first;
    std::uint64_t count;
};
PhotonShare photonShare(std::uint64_t photons, int rank, int size);

// runTrace across the ranks (docs/scaling.md): each traces its photonShare of settings.photons with its
// OpenMP threads; rank 0 returns the whole run (tallies merged exactly, so the same bits as one process;
// paths by photon; photons traced; `ranks`), the other ranks their own part. On rank 0 control.onProgress
// sees the run's total; a stop request (control.stop, a signal) on any rank stops them all, and rank 0
// then returns a partial result of every photon traced. With one rank this is runTrace.
TraceResult traceOnRanks(const Ranks& ranks, const OpticalScene& scene, const std::vector<Source>& sources,
                         const TraceSettings& settings, const TallySet& tallies, const TraceControl& control);

}  // namespace dropscope
