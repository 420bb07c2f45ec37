#pragma once

#include "snapshot/Image.hpp"

#include <cstddef>

namespace dropscope::test {

struct ImageDifference {
    bool sameSize = false;
    std::size_t pixels = 0;
    std::size_t differingPixels = 0;  // some channel differs by more than the tolerance
    int largestChannelDifference = 0;

    double differingShare() const {
        return pixels == 0 ? 0.0 : static_cast<double>(differingPixels) / static_cast<double>(pixels);
    }
    // Same size, and at most `maxDifferingShare` of the pixels differ.
    bool within(double maxDifferingShare) const { return sameSize && differingShare() <= maxDifferingShare; }
};

// Pixel by pixel: a pixel differs when any of its four channels differs by more than `channelTolerance`.
ImageDifference compareImages(const snapshot::Image& expected, const snapshot::Image& actual, int channelTolerance);

// For looking at a failure (same sizes only): the expected image as dim grey, every differing pixel pure
// red.
snapshot::Image differenceImage(const snapshot::Image& expected, const snapshot::Image& actual, int channelTolerance);

}  // namespace dropscope::test
