#include "scene/RandomStream.hpp"

namespace dropscope {

namespace {

// SplitMix64's finaliser (Steele, Lea and Flood 2014): a bijection that spreads every input bit
// over every output bit.
std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t stream) : engine_(splitMix64(splitMix64(seed) ^ stream)) {}

}  // namespace dropscope
