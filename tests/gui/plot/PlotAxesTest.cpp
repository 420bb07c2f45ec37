#include "gui/plot/PlotAxes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace dropscope::gui::plot {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A pixel computed from a value and back, through log10 and pow: a few roundings of values near 1.
constexpr double kRoundTrip = 1e-12;

std::vector<double> majorValues(const std::vector<Tick>& ticks) {
    std::vector<double> values;
    for (const Tick& tick : ticks) {
        if (tick.major) values.push_back(tick.value);
    }
    return values;
}
std::vector<std::string> majorLabels(const std::vector<Tick>& ticks) {
    std::vector<std::string> labels;
    for (const Tick& tick : ticks) {
        if (tick.major) labels.push_back(tick.label);
    }
    return labels;
}
std::size_t minorCount(const std::vector<Tick>& ticks) {
    std::size_t count = 0;
    for (const Tick& tick : ticks) {
        if (!tick.major) {
            ++count;
            EXPECT_EQ(tick.label, "") << "minor tick at " << tick.value;
        }
    }
    return count;
}

TEST(LinearTicks, ZeroTo180DegreesInStepsOf20) {
    const std::vector<Tick> ticks = linearTicks({0.0, 180.0}, 10);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{0, 20, 40, 60, 80, 100, 120, 140, 160, 180}));
    EXPECT_EQ(majorLabels(ticks),
              (std::vector<std::string>{"0", "20", "40", "60", "80", "100", "120", "140", "160", "180"}));
    EXPECT_EQ(minorCount(ticks), 0u);
}

TEST(LinearTicks, FewerTicksAllowedTakeTheNextStepOf125) {
    EXPECT_EQ(majorValues(linearTicks({0.0, 180.0}, 7)), (std::vector<double>{0, 50, 100, 150}));
    EXPECT_EQ(majorValues(linearTicks({0.0, 180.0}, 2)), (std::vector<double>{0, 100}));
}

TEST(LinearTicks, ASymmetricRatioAxis) {
    const std::vector<Tick> ticks = linearTicks({-1.0, 1.0}, 5);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0}));
    EXPECT_EQ(majorLabels(ticks), (std::vector<std::string>{"-1.0", "-0.5", "0", "0.5", "1.0"}));
}

TEST(LinearTicks, DecimalTicksAreTheDecimalsTheyAreLabelled) {
    // The end 0.1 + 0.2 is one bit above 0.3; 0.3 keeps its tick, and is 0.3, not 3 x 0.1.
    const std::vector<Tick> ticks = linearTicks({0.0, 0.1 + 0.2}, 4);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{0.0, 0.1, 0.2, 0.3}));
    EXPECT_EQ(majorLabels(ticks), (std::vector<std::string>{"0", "0.1", "0.2", "0.3"}));
}

TEST(LinearTicks, VerySmallAndVeryLargeValuesAreLabelledWithExponents) {
    EXPECT_EQ(majorLabels(linearTicks({0.0, 3e-6}, 4)), (std::vector<std::string>{"0", "1e-6", "2e-6", "3e-6"}));
    EXPECT_EQ(majorValues(linearTicks({0.0, 3e-6}, 4)), (std::vector<double>{0.0, 1e-6, 2e-6, 3e-6}));
    EXPECT_EQ(majorLabels(linearTicks({1e-6, 2e-6}, 3)), (std::vector<std::string>{"1.0e-6", "1.5e-6", "2.0e-6"}));
    EXPECT_EQ(majorLabels(linearTicks({0.0, 3e5}, 4)), (std::vector<std::string>{"0", "1e5", "2e5", "3e5"}));
}

TEST(LinearTicks, ANarrowRangeFarFromZeroEnds) {
    // Multiples of the step near 1e17 are beyond the doubles' whole numbers: counting them must still end.
    const std::vector<Tick> ticks = linearTicks({1e20, 1e20 + 1e5}, 5);
    EXPECT_LE(majorValues(ticks).size(), 5u);
}

TEST(LinearTicks, NoTicksForADegenerateRange) {
    EXPECT_TRUE(linearTicks({1.0, 1.0}, 5).empty());
    EXPECT_TRUE(linearTicks({2.0, 1.0}, 5).empty());
    EXPECT_TRUE(linearTicks({kNaN, 1.0}, 5).empty());
    EXPECT_TRUE(linearTicks({0.0, std::numeric_limits<double>::infinity()}, 5).empty());
}

TEST(LogTicks, EveryDecadeWithMinorTicksBetween) {
    const std::vector<Tick> ticks = logTicks({1e-5, 3e2}, 10);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2}));
    EXPECT_EQ(majorLabels(ticks),
              (std::vector<std::string>{"1e-5", "1e-4", "1e-3", "1e-2", "1e-1", "1e0", "1e1", "1e2"}));
    // 2..9 x 10^k in each of the seven whole decades, then 200 and 300 (the end).
    EXPECT_EQ(minorCount(ticks), 7u * 8u + 2u);
    for (std::size_t k = 1; k < ticks.size(); ++k) EXPECT_LT(ticks[k - 1].value, ticks[k].value);
}

TEST(LogTicks, ManyDecadesAreLabelledEverySecondOneWithTheRestAsMinorTicks) {
    const std::vector<Tick> ticks = logTicks({1e-5, 3e2}, 4);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{1e-4, 1e-2, 1e0, 1e2}));
    EXPECT_EQ(minorCount(ticks), 4u);  // 1e-5, 1e-3, 1e-1, 1e1
}

TEST(LogTicks, DecadesNearOneArePlainNumbers) {
    EXPECT_EQ(majorLabels(logTicks({0.01, 100.0}, 10)), (std::vector<std::string>{"0.01", "0.1", "1", "10", "100"}));
}

TEST(LogTicks, LessThanTwoDecadesGetsLinearTicks) {
    const std::vector<Tick> ticks = logTicks({2.0, 5.0}, 10);
    EXPECT_EQ(majorValues(ticks), (std::vector<double>{2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0}));
}

TEST(LogTicks, NoTicksWithoutAPositiveRange) {
    EXPECT_TRUE(logTicks({0.0, 10.0}, 5).empty());
    EXPECT_TRUE(logTicks({-1.0, 10.0}, 5).empty());
    EXPECT_TRUE(logTicks({10.0, 10.0}, 5).empty());
    EXPECT_TRUE(logTicks({kNaN, 10.0}, 5).empty());
}

TEST(AxisMapping, EndsLandOnTheirPixelsAndValuesComeBack) {
    const AxisMapping x{{0.0, 180.0}, Scale::Linear, 100.0, 700.0};
    EXPECT_EQ(x.toPixel(0.0), 100.0);
    EXPECT_EQ(x.toPixel(180.0), 700.0);
    EXPECT_EQ(x.toPixel(90.0), 400.0);
    const AxisMapping y{{1e-5, 1e3}, Scale::Log, 500.0, 100.0};  // upwards, as a y axis on screen
    EXPECT_NEAR(y.toPixel(1e-5), 500.0, kRoundTrip);
    EXPECT_NEAR(y.toPixel(1e3), 100.0, kRoundTrip);
    EXPECT_NEAR(y.toPixel(1e-1), 300.0, kRoundTrip);  // half way in decades
    std::mt19937_64 random(7);
    for (int i = 0; i < 1000; ++i) {
        const double linear = std::uniform_real_distribution<double>(-50.0, 250.0)(random);
        EXPECT_NEAR(x.toValue(x.toPixel(linear)), linear, kRoundTrip * 180.0) << "case " << i;
        const double logarithmic = std::pow(10.0, std::uniform_real_distribution<double>(-8.0, 5.0)(random));
        EXPECT_NEAR(y.toValue(y.toPixel(logarithmic)) / logarithmic, 1.0, kRoundTrip) << "case " << i;
    }
}

TEST(AxisMapping, ValuesWithNoPlaceOnTheAxisHaveNoPixel) {
    const AxisMapping y{{1e-5, 1e3}, Scale::Log, 500.0, 100.0};
    EXPECT_TRUE(std::isnan(y.toPixel(0.0)));
    EXPECT_TRUE(std::isnan(y.toPixel(-1.0)));
    EXPECT_TRUE(std::isnan(y.toPixel(kNaN)));
    const AxisMapping x{{0.0, 1.0}, Scale::Linear, 0.0, 100.0};
    EXPECT_TRUE(std::isnan(x.toPixel(kNaN)));
    EXPECT_TRUE(std::isnan(x.toPixel(-std::numeric_limits<double>::infinity())));
    EXPECT_EQ(x.toPixel(-1.0), -100.0);  // off the axis but drawable (clipped by the frame)
}

// Labels 7 pixels a character, as ImGui's default font.
double labelWidth(const std::string& label) { return 7.0 * static_cast<double>(label.size()); }

TEST(FittedTicks, AsManyTicksAsTheirLabelsHaveRoomFor) {
    EXPECT_EQ(majorValues(fittedTicks({{0.0, 180.0}, Scale::Linear, 0.0, 600.0}, labelWidth, 26.0)),
              (std::vector<double>{0, 20, 40, 60, 80, 100, 120, 140, 160, 180}));
    EXPECT_EQ(majorValues(fittedTicks({{0.0, 180.0}, Scale::Linear, 0.0, 200.0}, labelWidth, 26.0)),
              (std::vector<double>{0, 50, 100, 150}));
}

TEST(FittedTicks, NeighbouringLabelsNeverOverlapOnRandomAxes) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const Scale scale = i % 2 == 0 ? Scale::Linear : Scale::Log;
        const double lo = scale == Scale::Log ? std::pow(10.0, -12.0 + 14.0 * unit(random)) : -1e3 + 2e3 * unit(random);
        const double hi = scale == Scale::Log ? lo * std::pow(10.0, 8.0 * unit(random) + 0.01)
                                              : lo + std::pow(10.0, -3.0 + 6.0 * unit(random));
        const AxisMapping axis{{lo, hi}, scale, 0.0, 80.0 + 900.0 * unit(random)};
        const double gap = 10.0;
        const std::vector<Tick> ticks = fittedTicks(axis, labelWidth, gap);
        const std::vector<double> values = majorValues(ticks);
        const std::vector<std::string> labels = majorLabels(ticks);
        if (values.size() <= 2) continue;  // the coarsest ticks are kept even where they do not fit
        for (std::size_t k = 1; k < values.size(); ++k) {
            const double apart = axis.toPixel(values[k]) - axis.toPixel(values[k - 1]);
            EXPECT_GE(apart, 0.5 * (labelWidth(labels[k]) + labelWidth(labels[k - 1])) + gap)
                << "case " << i << ": " << labels[k - 1] << " and " << labels[k] << " on [" << lo << ", " << hi << "]";
        }
    }
}

}  // namespace
}  // namespace dropscope::gui::plot
