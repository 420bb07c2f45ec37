#pragma once

#include "tally/FixedPointSum.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope {

// A tally's scores as bytes, to merge runs made in other processes (MPI ranks, docs/scaling.md): a
// tally's writeScores appends them, and readScores of an emptyCopy() of the same tally (same bins,
// filters and scene) in another process restores them bit for bit. Native byte order and sizes:
// every rank of a run is the same program.
class ScoreWriter {
public:
    explicit ScoreWriter(std::vector<std::byte>& bytes) : bytes_(bytes) {}

    void word(std::uint64_t value) { raw(&value, sizeof value); }
    void real(double value) { raw(&value, sizeof value); }
    void sum(const FixedPointSum& value) {
        const auto [low, high] = value.bits();
        word(low);
        word(high);
    }
    // A length, then the values.
    void words(const std::vector<std::uint64_t>& values) {
        word(values.size());
        raw(values.data(), values.size() * sizeof(std::uint64_t));
    }
    template <std::size_t N>
    void words(const std::array<std::uint64_t, N>& values) {
        raw(values.data(), N * sizeof(std::uint64_t));
    }
    void sums(const std::vector<FixedPointSum>& values) {
        word(values.size());
        for (const FixedPointSum& value : values) sum(value);
    }

private:
    void raw(const void* data, std::size_t size) {
        if (size == 0) return;
        const std::size_t at = bytes_.size();
        bytes_.resize(at + size);
        std::memcpy(bytes_.data() + at, data, size);
    }

    std::vector<std::byte>& bytes_;
};

// Reads what a ScoreWriter wrote, in the same order. Throws std::runtime_error when the bytes end early
// or a length differs from the tally's own: the bytes came from a different run.
class ScoreReader {
public:
    explicit ScoreReader(std::span<const std::byte> bytes) : bytes_(bytes) {}

    std::uint64_t word() {
        std::uint64_t value = 0;
        raw(&value, sizeof value);
        return value;
    }
    double real() {
        double value = 0.0;
        raw(&value, sizeof value);
        return value;
    }
    FixedPointSum sum() {
        const std::uint64_t low = word();
        return FixedPointSum::fromBits(low, word());
    }
    // Into a vector of the length that was written (the tally's own bins).
    void words(std::vector<std::uint64_t>& values) {
        checkLength(values.size());
        raw(values.data(), values.size() * sizeof(std::uint64_t));
    }
    template <std::size_t N>
    void words(std::array<std::uint64_t, N>& values) {
        raw(values.data(), N * sizeof(std::uint64_t));
    }
    void sums(std::vector<FixedPointSum>& values) {
        checkLength(values.size());
        for (FixedPointSum& value : values) value = sum();
    }
    bool atEnd() const { return next_ == bytes_.size(); }
    // A count of items written after it, each at least `itemBytes` long: refused when the bytes left cannot
    // hold them (bytes of another run), before anything is allocated for them.
    std::uint64_t count(std::size_t itemBytes) {
        const std::uint64_t items = word();
        if (items > (bytes_.size() - next_) / itemBytes) throw std::runtime_error("tally scores: the bytes end early");
        return items;
    }

private:
    void checkLength(std::size_t expected) {
        const std::uint64_t length = word();
        if (length != expected) {
            throw std::runtime_error("tally scores: " + std::to_string(length) + " values where the tally has " +
                                     std::to_string(expected) + " (another run's scores)");
        }
    }
    void raw(void* data, std::size_t size) {
        if (size > bytes_.size() - next_) throw std::runtime_error("tally scores: the bytes end early");
        if (size > 0) std::memcpy(data, bytes_.data() + next_, size);
        next_ += size;
    }

    std::span<const std::byte> bytes_;
    std::size_t next_ = 0;
};

}  // namespace dropscope
