// FixedPointSum: the same bits for any order and grouping of the same values, within its resolution
// of the exact sum, and refusing what it cannot hold.
#include "tally/FixedPointSum.hpp"
#include "tally/ScoreBytes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace dropscope {
namespace {

// Weights of a weighted Monte Carlo run: mostly O(1), some tiny, some negative (Stokes Q, U, V).
std::vector<double> weights(unsigned seed, std::size_t count) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> values(count);
    for (double& v : values) v = unit(random) * std::pow(10.0, -6.0 * std::abs(unit(random)));
    return values;
}

TEST(FixedPointSum, AnyOrderAndGroupingGivesTheSameBits) {
    for (unsigned seed = 0; seed < 20; ++seed) {
        std::vector<double> values = weights(seed, 5000);
        FixedPointSum inOrder;
        for (double v : values) inOrder.add(v);
        std::mt19937_64 shuffle(seed + 100);
        std::shuffle(values.begin(), values.end(), shuffle);
        // Split into "threads" of uneven size, summed separately and merged in reverse.
        std::vector<FixedPointSum> parts(7);
        for (std::size_t i = 0; i < values.size(); ++i) parts[(i * i) % parts.size()].add(values[i]);
        FixedPointSum merged;
        for (auto part = parts.rbegin(); part != parts.rend(); ++part) merged += *part;
        EXPECT_EQ(merged, inOrder) << "seed " << seed;
        EXPECT_EQ(merged.value(), inOrder.value()) << "seed " << seed;
    }
}

TEST(FixedPointSum, PlainDoubleSumsDependOnTheOrderButThisDoesNot) {
    // The reason it exists: 1e16 + 1 - 1e16 is 0 or 1 depending on the order in doubles.
    FixedPointSum a, b;
    a.add(1e16);
    a.add(1.0);
    a.add(-1e16);
    b.add(1e16);
    b.add(-1e16);
    b.add(1.0);
    EXPECT_EQ(a.value(), 1.0);
    EXPECT_EQ(b.value(), 1.0);
    EXPECT_NE((1e16 + 1.0) - 1e16, (1e16 - 1e16) + 1.0);
}

TEST(FixedPointSum, IsWithinItsResolutionOfTheExactSum) {
    // Each value is rounded once to a multiple of 2^-64, so n values are within n 2^-65 of the
    // exact sum, then rounded to double once. The reference is a long double sum of values that are
    // multiples of 2^-20 (exact in both).
    std::vector<double> values = weights(7, 10000);
    for (double& v : values) v = std::ldexp(std::round(std::ldexp(v, 20)), -20);
    FixedPointSum sum;
    long double exact = 0.0L;
    for (double v : values) {
        sum.add(v);
        exact += v;
    }
    EXPECT_EQ(sum.value(), static_cast<double>(exact));
    FixedPointSum tiny;
    tiny.add(0x1p-66);  // below half the resolution: rounds to 0
    tiny.add(0x1p-63);
    EXPECT_EQ(tiny.value(), 0x1p-63);
}

TEST(FixedPointSum, RefusesValuesAndSumsOutOfRange) {
    FixedPointSum sum;
    EXPECT_THROW(sum.add(std::nan("")), std::domain_error);
    EXPECT_THROW(sum.add(INFINITY), std::domain_error);
    EXPECT_THROW(sum.add(0x1p62), std::domain_error);
    sum.add(0x1p61);
    sum.add(0x1p61 - 0x1p9);
    EXPECT_THROW(sum.add(0x1p9), std::overflow_error);
    EXPECT_EQ(sum.value(), 0x1p62 - 0x1p9);  // unchanged by the refused addition
    FixedPointSum other;
    other.add(0x1p61);
    EXPECT_THROW(sum += other, std::overflow_error);
}

TEST(FixedPointSum, TravelsAsTwoWordsBitForBit) {
    for (const double value : {0.0, 1.0, -1.0, 0x1p-64, -0x1p-64, 0.1, -3.7e17, 0x1p61}) {
        FixedPointSum sum;
        sum.add(value);
        sum.add(value / 3.0);
        const auto [low, high] = sum.bits();
        EXPECT_EQ(FixedPointSum::fromBits(low, high), sum) << value;
        std::vector<std::byte> bytes;
        ScoreWriter out(bytes);
        out.sum(sum);
        ScoreReader in(bytes);
        EXPECT_EQ(in.sum(), sum) << value;
        EXPECT_TRUE(in.atEnd());
    }
    // 2^126 units (2^62) is beyond any sum's range.
    EXPECT_THROW(FixedPointSum::fromBits(0, std::uint64_t{1} << 62), std::overflow_error);
}

TEST(ScoreBytes, ALengthOfAnotherTallyOrTooFewBytesIsRefused) {
    std::vector<std::byte> bytes;
    ScoreWriter out(bytes);
    out.words(std::vector<std::uint64_t>{1, 2, 3});
    std::vector<std::uint64_t> four(4);
    ScoreReader wrongLength(bytes);
    EXPECT_THROW(wrongLength.words(four), std::runtime_error);
    std::vector<std::uint64_t> three(3);
    ScoreReader right(bytes);
    right.words(three);
    EXPECT_EQ(three, (std::vector<std::uint64_t>{1, 2, 3}));
    EXPECT_THROW(right.word(), std::runtime_error);
}

}  // namespace
}  // namespace dropscope
