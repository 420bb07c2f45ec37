#pragma once

#include "transport/TraceRun.hpp"

#include <gtest/gtest.h>

namespace dropscope::test {

// Two runs' tallies agree count for count (the integer tallies are exactly reproducible).
inline void expectSameTally(const TraceTally& a, const TraceTally& b) {
    EXPECT_EQ(a.photons, b.photons);
    EXPECT_EQ(a.escaped, b.escaped);
    EXPECT_EQ(a.absorbed, b.absorbed);
    EXPECT_EQ(a.lost, b.lost);
    EXPECT_EQ(a.unscattered, b.unscattered);
    EXPECT_EQ(a.events, b.events);
    EXPECT_EQ(a.lostReasons, b.lostReasons);
    EXPECT_EQ(a.angular, b.angular);
}

}  // namespace dropscope::test
