#pragma once

#include "gui/plot/PlotData.hpp"

#include <functional>
#include <string>
#include <vector>

// An axis of a plot: where a value is drawn, and the ticks with their labels.
namespace dropscope::gui::plot {

// Whether `value` has a place on an axis of this scale: finite, and positive on a log axis.
bool drawable(double value, Scale scale);

// Data <-> pixels along one axis: range.lo at pixelLo, range.hi at pixelHi (on a y axis pixelHi is
// above, so smaller). Linear in the value, or in log10 of it on a log axis (range.lo > 0 there).
struct AxisMapping {
    AxisRange range;
    Scale scale = Scale::Linear;
    double pixelLo = 0.0;
    double pixelHi = 1.0;

    // NaN for a value that is not drawable.
    double toPixel(double value) const;
    double toValue(double pixel) const;
};

// A tick mark; major ticks carry a label, minor ones (a log axis's 2..9 x 10^k) an empty one.
struct Tick {
    double value = 0.0;
    std::string label;
    bool major = true;
    friend bool operator==(const Tick&, const Tick&) = default;
};

// At most `maxMajor` (>= 2) major ticks at multiples of 1, 2 or 5 x 10^k, the finest such step that
// fits. Empty when the range is not finite with lo < hi.
std::vector<Tick> linearTicks(AxisRange range, int maxMajor);
// Decades (every 1, 2, 5, 10, ... decades, the finest that fits) with the decades or the 2..9 x 10^k
// between as minor ticks; a range holding fewer than two decades gets linear ticks instead. Empty when
// lo <= 0 or the range is not finite with lo < hi.
std::vector<Tick> logTicks(AxisRange range, int maxMajor);
std::vector<Tick> axisTicks(AxisRange range, Scale scale, int maxMajor);

// The ticks with the most major ticks whose labels, each `labelExtent` long along the axis and centred
// on its tick, keep `gap` pixels apart over `mapping`. At least two major ticks where the range allows.
std::vector<Tick> fittedTicks(const AxisMapping& mapping, const std::function<double(const std::string&)>& labelExtent,
                              double gap);

}  // namespace dropscope::gui::plot
