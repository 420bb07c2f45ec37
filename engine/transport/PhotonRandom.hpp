#pragma once

#include <Random123/philox.h>

#include <cstdint>

namespace dropscope {

// The random numbers of one photon: Philox4x64-10 (Random123) keyed by the run's seed, counting
// through blocks of the photon's own counter space. A photon's numbers depend only on (seed, photon
// index, stream), so a trace is bit-identical whatever the thread count or the order photons are run in.
// Stream kTransportStream is its path (emission point, absorption, reflection); kSourceStream its
// wavelength and its direction within a divergent beam, so that giving a source a spectrum or a
// divergence leaves the path's own numbers where they were.
class PhotonRandom {
public:
    static constexpr std::uint64_t kTransportStream = 0;
    static constexpr std::uint64_t kSourceStream = 1;

    PhotonRandom(std::uint64_t seed, std::uint64_t photon, std::uint64_t stream = kTransportStream)
        : key_{{seed, 0x64726f7073636f70ULL}}, counter_{{photon, 0, stream, 0}} {}

    std::uint64_t bits() {
        if (next_ == kBlockSize) refill();
        return block_[next_++];
    }
    // In (0, 1), never 0 or 1: (2k + 1) * 2^-53 with k the top 52 bits of one output, so -log(u) and
    // 1/u are finite and u and 1 - u are equally likely.
    double uniform() { return static_cast<double>(((bits() >> 12) << 1) | 1U) * 0x1p-53; }

private:
    using Generator = r123::Philox4x64;
    static constexpr unsigned kBlockSize = 4;

    void refill() {
        block_ = Generator{}(counter_, key_);
        ++counter_[1];
        next_ = 0;
    }

    Generator::key_type key_;
    Generator::ctr_type counter_;
    Generator::ctr_type block_{};
    unsigned next_ = kBlockSize;
};

}  // namespace dropscope
