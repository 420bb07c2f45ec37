#include "transport/PhotonRandom.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope {
namespace {

TEST(PhotonRandom, PhiloxMatchesThePublishedKnownAnswer) {
    // Random123's kat_vectors: philox4x64-10 with counter and key all zero.
    const r123::Philox4x64::ctr_type output = r123::Philox4x64{}({{0, 0, 0, 0}}, {{0, 0}});
    EXPECT_EQ(output[0], 0x16554d9eca36314cULL);
    EXPECT_EQ(output[1], 0xdb20fe9d672d0fdcULL);
    EXPECT_EQ(output[2], 0xd7e772cee186176bULL);
    EXPECT_EQ(output[3], 0x7e68b68aec7ba23bULL);
}

TEST(PhotonRandom, APhotonsNumbersDependOnlyOnSeedAndPhoton) {
    PhotonRandom a(42, 7);
    PhotonRandom b(42, 7);
    for (int i = 0; i < 100; ++i) ASSERT_EQ(a.bits(), b.bits());
}

TEST(PhotonRandom, NeighbouringPhotonsAndSeedsAreUnrelated) {
    PhotonRandom base(42, 7);
    PhotonRandom nextPhoton(42, 8);
    PhotonRandom nextSeed(43, 7);
    int equal = 0;
    for (int i = 0; i < 1000; ++i) {
        const std::uint64_t x = base.bits();
        equal += x == nextPhoton.bits();
        equal += x == nextSeed.bits();
    }
    EXPECT_EQ(equal, 0);
}

TEST(PhotonRandom, UniformIsOpenAndHasTheMomentsOfU01) {
    // Mean 1/2 and variance 1/12 within five standard errors over 1e6 draws from 1e4 photons.
    constexpr int kPhotons = 10000;
    constexpr int kDraws = 100;
    double sum = 0.0;
    double sumSquares = 0.0;
    for (int photon = 0; photon < kPhotons; ++photon) {
        PhotonRandom random(1, static_cast<std::uint64_t>(photon));
        for (int i = 0; i < kDraws; ++i) {
            const double u = random.uniform();
            ASSERT_GT(u, 0.0);
            ASSERT_LT(u, 1.0);
            sum += u;
            sumSquares += (u - 0.5) * (u - 0.5);
        }
    }
    const double n = kPhotons * kDraws;
    EXPECT_NEAR(sum / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
    EXPECT_NEAR(sumSquares / n, 1.0 / 12.0, 5.0 * std::sqrt(1.0 / 180.0 / n));  // Var((u-1/2)^2) = 1/180
}

}  // namespace
}  // namespace dropscope
