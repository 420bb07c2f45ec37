#include "render/ImageComparison.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace dropscope::test {

namespace {

int largestDifference(const std::uint8_t* a, const std::uint8_t* b) {
    int largest = 0;
    for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int{a[c]} - int{b[c]}));
    return largest;
}

}  // namespace

ImageDifference compareImages(const snapshot::Image& expected, const snapshot::Image& actual, int channelTolerance) {
    ImageDifference difference;
    difference.sameSize = expected.width == actual.width && expected.height == actual.height;
    if (!difference.sameSize) return difference;
    difference.pixels = static_cast<std::size_t>(expected.width) * static_cast<std::size_t>(expected.height);
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const int largest = largestDifference(expected.pixel(x, y), actual.pixel(x, y));
            difference.largestChannelDifference = std::max(difference.largestChannelDifference, largest);
            if (largest > channelTolerance) ++difference.differingPixels;
        }
    }
    return difference;
}

snapshot::Image differenceImage(const snapshot::Image& expected, const snapshot::Image& actual, int channelTolerance) {
    if (expected.width != actual.width || expected.height != actual.height) {
        throw std::invalid_argument("differenceImage: the images differ in size");
    }
    snapshot::Image out{expected.width, expected.height, std::vector<std::uint8_t>(expected.rgba.size())};
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const std::uint8_t* e = expected.pixel(x, y);
            std::uint8_t* o = &out.rgba[4 * (static_cast<std::size_t>(y) * out.width + x)];
            const int largest = largestDifference(e, actual.pixel(x, y));
            if (largest > channelTolerance) {
                o[0] = 255;
                o[1] = 0;
                o[2] = 0;
            } else {
                const auto grey = static_cast<std::uint8_t>((int{e[0]} + int{e[1]} + int{e[2]}) / 9);
                o[0] = o[1] = o[2] = grey;
            }
            o[3] = 255;
        }
    }
    return out;
}

}  // namespace dropscope::test
