#pragma once

#include "run/TraceRun.hpp"
#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"
#include "tally/StandardTallies.hpp"

#include <gtest/gtest.h>

namespace dropscope::test {

inline const FateTally& fates(const TraceResult& result) { return result.tallies.get<FateTally>(); }
inline const AngularTally& angular(const TraceResult& result) { return result.tallies.get<AngularTally>(); }

// A run with what `dropscope trace` counts (standardTallies), `bins` angular bins, Stokes columns when the
// settings trace polarisation.
inline TraceResult traceStandard(const OpticalScene& scene, const std::vector<Source>& sources,
                                 const TraceSettings& settings, int bins = 180, const TraceControl& control = {}) {
    return runTrace(scene, sources, settings, standardTallies(bins, settings.transport.polarisation), control);
}

// The share of a run's photons that `count` is.
inline double fraction(std::uint64_t count, const TraceResult& result) {
    return static_cast<double>(count) / static_cast<double>(fates(result).photons());
}

// Two runs' standard tallies agree count for count (integer tallies are exactly reproducible).
inline void expectSameTally(const TraceResult& a, const TraceResult& b) {
    EXPECT_EQ(a.photons, b.photons);
    EXPECT_EQ(fates(a), fates(b));
    EXPECT_EQ(angular(a), angular(b));
}

}  // namespace dropscope::test
