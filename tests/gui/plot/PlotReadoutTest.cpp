#include "gui/plot/PlotReadout.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace dropscope::gui::plot {
namespace {

TEST(NearestSample, TheNearestXAndTheLowerOfTwoAsNear) {
    const std::vector<double> x{0.0, 1.0, 2.0, 3.0};
    EXPECT_EQ(nearestSample(x, 4, 1.4), 1u);
    EXPECT_EQ(nearestSample(x, 4, 1.6), 2u);
    EXPECT_EQ(nearestSample(x, 4, 1.5), 1u);
    EXPECT_EQ(nearestSample(x, 4, 2.0), 2u);
    EXPECT_EQ(nearestSample(x, 4, -5.0), 0u);
    EXPECT_EQ(nearestSample(x, 4, 10.0), 3u);
    EXPECT_EQ(nearestSample(x, 2, 10.0), 1u) << "only the first `count` samples";
    EXPECT_FALSE(nearestSample(x, 4, std::numeric_limits<double>::quiet_NaN()));
    EXPECT_FALSE(nearestSample({}, 0, 1.0));
}

TEST(Readout, EachCurvesNearestSampleInFullPrecision) {
    const SubPlot subPlot{
        "I", {{"a", {0.0, 10.0, 20.0}, {1.0, 0.123456789, 3.0}}, {"empty", {}, {}}, {"b", {0.0, 15.0}, {5.0, 6.0}}}};
    const Readout readout = readoutAt(subPlot, 1, 11.0);
    EXPECT_EQ(readout.subPlot, 1u);
    EXPECT_EQ(readout.cursorX, 11.0);
    ASSERT_EQ(readout.samples.size(), 2u) << "a curve without samples is left out";
    EXPECT_EQ(readout.samples[0], (CurveSample{0, "a", 1, 10.0, 0.123456789}));
    EXPECT_EQ(readout.samples[1], (CurveSample{2, "b", 1, 15.0, 6.0}));
    EXPECT_EQ(readoutLines(readout, "angle (deg)"),
              (std::vector<std::string>{"angle (deg) = 10", "a = 0.123457", "b = 6 at 15"}));
}

TEST(Readout, WithoutSamplesItGivesTheCursor) {
    const Readout readout = readoutAt(SubPlot{"I", {}}, 0, 42.25);
    EXPECT_TRUE(readout.samples.empty());
    EXPECT_EQ(readoutLines(readout, "x"), (std::vector<std::string>{"x = 42.25"}));
}

}  // namespace
}  // namespace dropscope::gui::plot
