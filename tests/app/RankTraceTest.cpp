// The pieces of an MPI run that need no MPI: the photon shares, the one-rank fallback, SIGTERM as Ctrl-C.
#include "cli/InterruptGuard.hpp"
#include "cli/RankTrace.hpp"
#include "cli/Ranks.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <limits>

namespace dropscope {
namespace {

TEST(PhotonShare, ConsecutiveSharesCoverEveryPhotonOnceAndDifferByOneAtMost) {
    for (const std::uint64_t photons : {std::uint64_t{0}, std::uint64_t{2}, std::uint64_t{10}, std::uint64_t{1000003},
                                        std::numeric_limits<std::uint64_t>::max()}) {
        for (const int size : {1, 2, 3, 7, 64}) {
            std::uint64_t next = 0;
            std::uint64_t least = std::numeric_limits<std::uint64_t>::max();
            std::uint64_t most = 0;
            for (int rank = 0; rank < size; ++rank) {
                const PhotonShare share = photonShare(photons, rank, size);
                EXPECT_EQ(share.first, next) << photons << " photons, rank " << rank << " of " << size;
                next = share.first + share.count;
                least = std::min(least, share.count);
                most = std::max(most, share.count);
            }
            EXPECT_EQ(next, photons) << photons << " photons on " << size << " ranks";
            EXPECT_LE(most - least, 1u) << photons << " photons on " << size << " ranks";
        }
    }
}

TEST(Ranks, WithoutALauncherThisIsTheOneRank) {
    const Ranks ranks;  // no mpirun in the test's environment
    EXPECT_EQ(ranks.rank(), 0);
    EXPECT_EQ(ranks.size(), 1);
    EXPECT_TRUE(ranks.root());
    EXPECT_FALSE(ranks.parallel());
    EXPECT_FALSE(ranks.launched());
    int calls = 0;
    ranks.together([&] { ++calls; });
    EXPECT_EQ(calls, 1);
    EXPECT_THROW(ranks.together([] { throw std::runtime_error("bad"); }), std::runtime_error);
}

TEST(InterruptGuard, UnderALauncherSigtermIsACtrlCAndBothHandlersAreRestored) {
    struct sigaction before {};
    ::sigaction(SIGTERM, nullptr, &before);
    {
        const InterruptGuard guard(InterruptGuard::kAlsoTerminate);
        EXPECT_FALSE(guard.interrupted());
        std::raise(SIGTERM);
        EXPECT_TRUE(guard.interrupted());
    }
    struct sigaction after {};
    ::sigaction(SIGTERM, nullptr, &after);
    EXPECT_EQ(after.sa_handler, before.sa_handler);
    {
        const InterruptGuard guard;  // Ctrl-C only: SIGTERM keeps its disposition
        struct sigaction during {};
        ::sigaction(SIGTERM, nullptr, &during);
        EXPECT_EQ(during.sa_handler, before.sa_handler);
    }
}

}  // namespace
}  // namespace dropscope
