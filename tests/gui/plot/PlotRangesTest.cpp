#include "gui/plot/PlotRanges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace dropscope::gui::plot {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Ranges computed with a multiplication or a pow of the values they are compared with.
constexpr double kRounding = 1e-12;

void expectRange(AxisRange actual, AxisRange expected) {
    EXPECT_NEAR(actual.lo, expected.lo, kRounding * std::abs(expected.lo) + kRounding);
    EXPECT_NEAR(actual.hi, expected.hi, kRounding * std::abs(expected.hi) + kRounding);
}

SubPlot subPlotOf(std::vector<double> x, std::vector<double> y) { return {"y", {{"c", std::move(x), std::move(y)}}}; }

TEST(PlotRanges, ASingleValueIsWidenedAroundIt) {
    expectRange(fittedRange(AxisRange{5.0, 5.0}, Scale::Linear, 0.05), {2.5, 7.5});
    expectRange(fittedRange(AxisRange{-4.0, -4.0}, Scale::Linear, 0.05), {-6.0, -2.0});
    expectRange(fittedRange(AxisRange{100.0, 100.0}, Scale::Log, 0.05),
                {100.0 / std::sqrt(10.0), 100.0 * std::sqrt(10.0)});
}

TEST(PlotRanges, AllZeroIsShownAroundZeroOnALinearAxisAndAsNothingOnALogAxis) {
    const SubPlot zeros = subPlotOf({0, 1, 2}, {0, 0, 0});
    const AxisRange x{0.0, 2.0};
    EXPECT_EQ(yAxisRange(zeros, Scale::Linear, x), (AxisRange{-1.0, 1.0}));
    EXPECT_FALSE(yExtent(zeros, Scale::Log, x));
    EXPECT_EQ(yAxisRange(zeros, Scale::Log, x), (AxisRange{1.0, 10.0}));
    EXPECT_FALSE(anyDrawable(zeros.curves[0], Scale::Log));
    EXPECT_TRUE(anyDrawable(zeros.curves[0], Scale::Linear));
}

TEST(PlotRanges, NaNAndInfinitiesAreLeftOutAndOnALogAxisSoAreValuesUpToZero) {
    const SubPlot data = subPlotOf({0, 1, 2, 3, 4, 5}, {kNaN, -3.0, 0.0, 0.5, kInf, 8.0});
    const AxisRange x{0.0, 5.0};
    EXPECT_EQ(yExtent(data, Scale::Linear, x), (AxisRange{-3.0, 8.0}));
    EXPECT_EQ(yExtent(data, Scale::Log, x), (AxisRange{0.5, 8.0}));
    expectRange(yAxisRange(data, Scale::Linear, x), {-3.0 - 0.55, 8.0 + 0.55});
    expectRange(yAxisRange(data, Scale::Log, x), {0.5 / std::pow(16.0, 0.05), 8.0 * std::pow(16.0, 0.05)});
    EXPECT_FALSE(yExtent(subPlotOf({0, 1}, {kNaN, kNaN}), Scale::Linear, x));
    EXPECT_FALSE(anyDrawable(subPlotOf({0, 1}, {kNaN, kNaN}).curves[0], Scale::Linear));
}

TEST(PlotRanges, ALogAxisOverSixHundredDecadesStaysPositiveAndFinite) {
    const AxisRange range = fittedRange(AxisRange{1e-300, 1e300}, Scale::Log, 0.05);
    EXPECT_GT(range.lo, 0.0);
    EXPECT_LT(range.lo, 1e-300);
    EXPECT_GT(range.hi, 1e300);
    EXPECT_TRUE(std::isfinite(range.hi)) << "the margin stops where the doubles do";
}

TEST(PlotRanges, TheYAxisFitsTheDataInTheXRangeShown) {
    const SubPlot data = subPlotOf({0, 1, 2, 3}, {100.0, 1.0, 2.0, 50.0});
    EXPECT_EQ(yExtent(data, Scale::Linear, {0.5, 2.5}), (AxisRange{1.0, 2.0}));
}

TEST(PlotRanges, AFixedYRangeIsKeptWhereTheScaleAllowsIt) {
    SubPlot ratio = subPlotOf({0, 1}, {0.2, 0.4});
    ratio.yRange = AxisRange{-1.0, 1.0};
    EXPECT_EQ(yAxisRange(ratio, Scale::Linear, {0.0, 1.0}), (AxisRange{-1.0, 1.0}));
    // -1 has no place on a log axis: fitted to the data instead.
    expectRange(yAxisRange(ratio, Scale::Log, {0.0, 1.0}), {0.2 / std::pow(2.0, 0.05), 0.4 * std::pow(2.0, 0.05)});
}

TEST(PlotRanges, TheWholeXAxisIsTheFiguresOrElseTheDatas) {
    Figure figure{"f", "x", std::nullopt, {subPlotOf({kNaN, 2.0, 7.0}, {1, 1, 1}), subPlotOf({-1.0, 3.0}, {1, 1})}};
    EXPECT_EQ(fullXRange(figure), (AxisRange{-1.0, 7.0}));
    figure.xRange = AxisRange{0.0, 180.0};
    EXPECT_EQ(fullXRange(figure), (AxisRange{0.0, 180.0}));
    EXPECT_EQ(fullXRange(Figure{}), (AxisRange{0.0, 1.0}));
}

TEST(PlotZoom, WheelZoomKeepsThePointUnderTheMouseInPlace) {
    const AxisRange full{0.0, 180.0};
    expectRange(zoomedAbout(full, full, 90.0, 0.5), {45.0, 135.0});
    expectRange(zoomedAbout(full, full, 30.0, 0.5), {15.0, 105.0});
    expectRange(zoomedAbout({45.0, 135.0}, full, 90.0, 2.0), full);
    EXPECT_EQ(zoomedAbout({45.0, 135.0}, full, 90.0, 10.0), full) << "zooming out stops at the whole axis";
}

TEST(PlotZoom, AViewStaysInsideTheWholeAxisAndIsNeverEmpty) {
    const AxisRange full{0.0, 180.0};
    EXPECT_EQ(clampedView({120.0, 60.0}, full), (AxisRange{60.0, 120.0})) << "dragged right to left";
    EXPECT_EQ(clampedView({170.0, 200.0}, full), (AxisRange{150.0, 180.0}));
    EXPECT_EQ(clampedView({-20.0, 10.0}, full), (AxisRange{0.0, 30.0}));
    EXPECT_EQ(clampedView({-20.0, 400.0}, full), full);
    EXPECT_NEAR(clampedView({50.0, 50.0}, full).span(), kMinViewFraction * 180.0, kRounding);
    EXPECT_EQ(clampedView({kNaN, 50.0}, full), full);
}

}  // namespace
}  // namespace dropscope::gui::plot
