#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace dropscope {

// A sum of doubles that is the same bits in any order and grouping: each value is rounded once to a
// multiple of 2^-kFractionBits and the multiples are added as 128-bit integers, which is associative.
// So a weighted score summed over threads (or ranks) merged in any order does not depend on their
// number. Resolution 2^-64 (5.4e-20) absolute; the sum must stay below 2^62 (4.6e18) in magnitude.
// (Floating-point addition is not associative: summed per thread and merged, a weighted score would
// change in its last bits with the thread count.)
class FixedPointSum {
public:
    static constexpr int kFractionBits = 64;
    static constexpr double kLimit = 0x1p62;
    static constexpr double kUnit = 0x1p64;  // 2^kFractionBits

    // Throws std::domain_error for a value that is not finite or not below kLimit in magnitude, and
    // std::overflow_error when the sum would leave that range.
    void add(double value) {
        if (!(std::abs(value) < kLimit)) throw std::domain_error("FixedPointSum: value out of range");
        addUnits(static_cast<Units>(std::nearbyint(value * kUnit)));  // exact: a power of two, no overflow
    }
    FixedPointSum& operator+=(const FixedPointSum& other) {
        addUnits(other.units_);
        return *this;
    }
    // The sum, rounded to the nearest double.
    double value() const { return std::ldexp(static_cast<double>(units_), -kFractionBits); }

    friend bool operator==(const FixedPointSum&, const FixedPointSum&) = default;

    // The sum's 128 bits as two words (low, high), and back: how it travels between processes
    // (tally/ScoreBytes.hpp). fromBits throws std::overflow_error for bits no sum can have.
    std::pair<std::uint64_t, std::uint64_t> bits() const {
        const auto word = static_cast<UnsignedUnits>(units_);
        return {static_cast<std::uint64_t>(word), static_cast<std::uint64_t>(word >> 64)};
    }
    static FixedPointSum fromBits(std::uint64_t low, std::uint64_t high) {
        const auto word = (static_cast<UnsignedUnits>(high) << 64) | low;
        FixedPointSum sum;
        sum.addUnits(static_cast<Units>(word));
        return sum;
    }

private:
    __extension__ typedef __int128 Units;  // __extension__: GCC and Clang have it, ISO C++ has not
    __extension__ typedef unsigned __int128 UnsignedUnits;
    static constexpr Units kMaxUnits = static_cast<Units>(1) << (62 + kFractionBits);

    // Both terms are below 2^126 in magnitude, so their sum cannot overflow the 128 bits.
    void addUnits(Units units) {
        const Units sum = units_ + units;
        if (sum >= kMaxUnits || sum <= -kMaxUnits) throw std::overflow_error("FixedPointSum: sum out of range");
        units_ = sum;
    }

    Units units_ = 0;
};

}  // namespace dropscope
