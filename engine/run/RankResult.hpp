#pragma once

#include "run/TraceRun.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace dropscope {

// A run split across processes (MPI ranks, docs/scaling.md): each process traces its own photons into a
// TraceResult. packRankResult packs what merges (photons traced, every tally's scores, recorded paths);
// mergeRankResult adds such a pack into another process's result of the same run (same tallies, from
// the same options and scene). Tallies merge exactly (tally/Tally.hpp), so the merged result is the same
// bits for any split. Throws std::runtime_error for bytes of another run.
std::vector<std::byte> packRankResult(const TraceResult& result);
void mergeRankResult(TraceResult& into, std::span<const std::byte> bytes);

}  // namespace dropscope
