#include "run/RunMemory.hpp"

#include "scene/MachineMemory.hpp"
#include "tally/DetectorTallies.hpp"
#include "tally/ScoreBytes.hpp"

#include <omp.h>

namespace dropscope {

TraceMemory estimateTraceMemory(const TallySet& tallies, const TraceSettings& settings, std::uint64_t records,
                                int ranks) {
    TraceMemory need;
    need.mergesRanks = ranks > 1;
    // An empty tally's scores are its counters, as the bytes ranks exchange: the size of one copy.
    std::vector<std::byte> bytes;
    ScoreWriter out(bytes);
    tallies.emptyCopy().writeScores(out);
    need.tallyBytes = static_cast<double>(bytes.size());
    need.threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
    need.pathBytes = static_cast<double>(std::min(settings.paths, settings.photons)) * kPathBytesEstimate;
    // In doubles: photons * 16 would wrap around for --photons near 2^64.
    const double recorded = std::min(static_cast<double>(records), static_cast<double>(settings.photons) * 16.0);
    need.recordBytes = recorded * static_cast<double>(sizeof(DetectorHit)) * (need.threads + 1);
    return need;
}

std::optional<std::string> traceMemoryProblem(const TraceMemory& need, double availableBytes) {
    if (!(need.total() > availableBytes)) return std::nullopt;
    return "this trace needs about " + bytesText(need.total()) + " (tallies " + bytesText(need.tallyBytes) +
           " per thread x " + std::to_string(need.threads) + " threads and " +
           (need.mergesRanks ? "four more copies to merge the ranks" : "two more copies") + ", paths " +
           bytesText(need.pathTotal()) + ", detector records " + bytesText(need.recordTotal()) + "), more than " +
           availableMemoryText(availableBytes) + " (docs/limits.md)";
}

}  // namespace dropscope
