#include "gui/plot/PlotReadout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace dropscope::gui::plot {

namespace {

// Six significant digits: more than a reader compares by eye, fewer than a double holds.
std::string valueText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace

std::optional<std::size_t> nearestSample(const std::vector<double>& x, std::size_t count, double at) {
    count = std::min(count, x.size());
    if (count == 0 || std::isnan(at)) return std::nullopt;
    const auto begin = x.begin();
    const auto end = begin + static_cast<std::ptrdiff_t>(count);
    const auto above = std::lower_bound(begin, end, at);
    if (above == begin) return 0;
    if (above == end) return count - 1;
    const auto below = std::prev(above);
    const auto nearest = at - *below <= *above - at ? below : above;
    return static_cast<std::size_t>(nearest - begin);
}

Readout readoutAt(const SubPlot& subPlot, std::size_t subPlotIndex, double cursorX) {
    Readout readout{subPlotIndex, cursorX, {}};
    for (std::size_t k = 0; k < subPlot.curves.size(); ++k) {
        const Curve& curve = subPlot.curves[k];
        if (const auto index = nearestSample(curve.x, sampleCount(curve), cursorX)) {
            readout.samples.push_back({k, curve.name, *index, curve.x[*index], curve.y[*index]});
        }
    }
    return readout;
}

std::vector<std::string> readoutLines(const Readout& readout, const std::string& xLabel) {
    const double x = readout.samples.empty() ? readout.cursorX : readout.samples.front().x;
    std::vector<std::string> lines{xLabel + " = " + valueText(x)};
    for (const CurveSample& sample : readout.samples) {
        std::string line = sample.name + " = " + valueText(sample.y);
        if (sample.x != x) line += " at " + valueText(sample.x);
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace dropscope::gui::plot
