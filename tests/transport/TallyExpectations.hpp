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

// Two runs of the same photons through surfaces that agree to rounding (a sphere and a parametric sphere):
// the same counts, and Stokes sums equal to `stokesTolerance` (a share of the photons traced).
inline void expectSameTallyToRounding(const TraceResult& a, const TraceResult& b, double stokesTolerance) {
    EXPECT_EQ(a.photons, b.photons);
    EXPECT_EQ(fates(a), fates(b));
    EXPECT_EQ(angular(a).escapes(), angular(b).escapes());
    const AngularTally::Columns ca = angular(a).columns();
    const AngularTally::Columns cb = angular(b).columns();
    ASSERT_EQ(ca.stokesQ.size(), cb.stokesQ.size());
    for (std::size_t bin = 0; bin < ca.stokesQ.size(); ++bin) {
        EXPECT_NEAR(ca.stokesQ[bin], cb.stokesQ[bin], stokesTolerance) << "bin " << bin;
        EXPECT_NEAR(ca.stokesU[bin], cb.stokesU[bin], stokesTolerance) << "bin " << bin;
        EXPECT_NEAR(ca.stokesV[bin], cb.stokesV[bin], stokesTolerance) << "bin " << bin;
    }
}

}  // namespace dropscope::test
