#pragma once

#include <cstdint>
#include <random>

namespace dropscope {

// Random numbers that are the same on every machine and compiler, for scene generators
// (docs/scene-format.md, "Reproducibility"). The engine is std::mt19937_64, whose output sequence the
// C++ standard fixes; the conversions to doubles are ours, because the standard distributions
// (std::uniform_real_distribution, std::normal_distribution, ...) are implementation-defined.
// Both conversions below are exact: no rounding, no libm.
class RandomStream {
public:
    // Stream `stream` of `seed`: the engine is seeded with a SplitMix64 mix of both, so the streams of
    // one seed (and the same stream of nearby seeds) are unrelated.
    RandomStream(std::uint64_t seed, std::uint64_t stream);

    std::uint64_t bits() { return engine_(); }
    // In [0, 1): k * 2^-53 with k the top 53 bits of one output.
    double uniform() { return static_cast<double>(bits() >> 11) * 0x1p-53; }
    // In (0, 1): (2k + 1) * 2^-53 with k the top 52 bits of one output. The values are symmetric about
    // 1/2 (u and 1 - u are equally likely and both exact), which inverse-CDF sampling of tails needs.
    double openUniform() { return static_cast<double>(((bits() >> 12) << 1) | 1U) * 0x1p-53; }

private:
    std::mt19937_64 engine_;
};

}  // namespace dropscope
