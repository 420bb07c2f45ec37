#pragma once

#include "gui/plot/PlotData.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

// The hover readout: each curve's sample nearest the cursor's x.
namespace dropscope::gui::plot {

// The index of the x nearest `at` (x ascending; the lower one of two as near); none for no x or a NaN `at`.
std::optional<std::size_t> nearestSample(const std::vector<double>& x, std::size_t count, double at);

struct CurveSample {
    std::size_t curve = 0;  // its index in the sub-plot
    std::string name;
    std::size_t index = 0;  // the sample's
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const CurveSample&, const CurveSample&) = default;
};

// What the tooltip over a sub-plot says: the cursor's x and each curve's nearest sample (curves without
// samples are left out).
struct Readout {
    std::size_t subPlot = 0;
    double cursorX = 0.0;
    std::vector<CurveSample> samples;
};

Readout readoutAt(const SubPlot& subPlot, std::size_t subPlotIndex, double cursorX);

// The tooltip's lines: "<x label> = <x>" with the first sample's x (the cursor's when none), then
// "<curve> = <y>", with " at <x>" where a curve's sample has another x; values as %.6g.
std::vector<std::string> readoutLines(const Readout& readout, const std::string& xLabel);

}  // namespace dropscope::gui::plot
