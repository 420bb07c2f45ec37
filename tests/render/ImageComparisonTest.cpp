// The golden comparison itself: the channel tolerance and the share of differing pixels.
#include "render/ImageComparison.hpp"
#include "render/RenderTolerances.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dropscope {
namespace {

using test::compareImages;
using test::kGoldenChannelTolerance;

snapshot::Image uniform(int width, int height, std::uint8_t value) {
    return {width, height, std::vector<std::uint8_t>(4 * static_cast<std::size_t>(width) * height, value)};
}

TEST(ImageComparison, PixelDiffersOnlyBeyondTheChannelTolerance) {
    const snapshot::Image expected = uniform(4, 3, 100);
    snapshot::Image actual = expected;
    actual.rgba[2] = static_cast<std::uint8_t>(100 + kGoldenChannelTolerance);  // pixel (0, 0), blue: within
    actual.rgba[4 * 5 + 3] =
        static_cast<std::uint8_t>(100 - kGoldenChannelTolerance - 1);  // pixel (1, 1), alpha: beyond
    const test::ImageDifference difference = compareImages(expected, actual, kGoldenChannelTolerance);
    EXPECT_TRUE(difference.sameSize);
    EXPECT_EQ(difference.pixels, 12u);
    EXPECT_EQ(difference.differingPixels, 1u);
    EXPECT_EQ(difference.largestChannelDifference, kGoldenChannelTolerance + 1);
}

TEST(ImageComparison, FailsOnlyBeyondTheShareOfDifferingPixels) {
    const snapshot::Image expected = uniform(100, 100, 0);  // 10,000 pixels: 5 may differ at 0.05 %
    snapshot::Image actual = expected;
    const auto allowed = static_cast<int>(test::kGoldenMaxDifferingShare * 10000);
    for (int k = 0; k < allowed; ++k) actual.rgba[4 * static_cast<std::size_t>(k) * 37] = 255;
    EXPECT_TRUE(compareImages(expected, actual, kGoldenChannelTolerance).within(test::kGoldenMaxDifferingShare));
    actual.rgba[4 * 9999] = 255;
    EXPECT_FALSE(compareImages(expected, actual, kGoldenChannelTolerance).within(test::kGoldenMaxDifferingShare));
}

TEST(ImageComparison, DifferentSizesNeverMatch) {
    const test::ImageDifference difference = compareImages(uniform(4, 3, 0), uniform(3, 4, 0), kGoldenChannelTolerance);
    EXPECT_FALSE(difference.sameSize);
    EXPECT_FALSE(difference.within(1.0));
}

TEST(ImageComparison, DifferenceImageMarksDifferingPixelsRed) {
    const snapshot::Image expected = uniform(2, 1, 90);
    snapshot::Image actual = expected;
    actual.rgba[4] = 200;  // pixel (1, 0)
    const snapshot::Image diff = test::differenceImage(expected, actual, kGoldenChannelTolerance);
    EXPECT_EQ(diff.pixel(0, 0)[0], diff.pixel(0, 0)[1]) << "an equal pixel is grey";
    EXPECT_EQ(diff.pixel(0, 0)[0], 30);
    EXPECT_EQ(diff.pixel(1, 0)[0], 255);
    EXPECT_EQ(diff.pixel(1, 0)[1], 0);
    EXPECT_EQ(diff.pixel(1, 0)[2], 0);
}

}  // namespace
}  // namespace dropscope
