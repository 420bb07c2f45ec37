#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

// What a plot window shows, as plain data: a panel fills a Figure each frame and hands it to
// drawPlotWindow (gui/PlotWindow.hpp). Nothing here knows ImGui. Every member has an initializer, so
// aggregates may give only the first few.
namespace dropscope::gui::plot {

enum class Scale { Linear, Log };

// An interval of an axis, lo < hi where an axis is drawn over it.
struct AxisRange {
    double lo = 0.0;
    double hi = 1.0;
    double span() const { return hi - lo; }
    friend bool operator==(const AxisRange&, const AxisRange&) = default;
};

// One named series, y[i] at x[i], with x ascending (the readout's nearest-sample search relies on it).
// Samples past the shorter of x and y are ignored. A y that is not finite, or not positive on a log
// axis, is a gap in the line.
struct Curve {
    std::string name{};  // the legend's entry and the CSV column's header
    std::vector<double> x{};
    std::vector<double> y{};
    // Its line's colour (sRGB components in [0, 1], used as they are); none: the window's palette, by
    // the curve's place in its sub-plot.
    std::optional<std::array<float, 3>> colour{};
};

inline std::size_t sampleCount(const Curve& curve) { return std::min(curve.x.size(), curve.y.size()); }

// One frame of a figure: curves over the shared x axis against their own y axis.
struct SubPlot {
    std::string yLabel{};
    std::vector<Curve> curves{};
    Scale defaultScale = Scale::Linear;  // until the user switches it (PlotWindowState::scales)
    std::optional<AxisRange> yRange{};   // a fixed y axis (a ratio in [-1, 1]); otherwise fitted to the data
};

// A plot window's content: sub-plots stacked top to bottom, sharing the x axis.
struct Figure {
    std::string title{};  // the window's title; ImGui tells windows apart by it, so one per figure
    std::string xLabel{};
    std::optional<AxisRange> xRange{};  // the whole x axis (0-180 degrees); otherwise the data's extent
    std::vector<SubPlot> subPlots{};
};

}  // namespace dropscope::gui::plot
