#pragma once

#include "gui/plot/PlotData.hpp"
#include "gui/plot/PlotReadout.hpp"

#include <optional>
#include <string>
#include <vector>

namespace dropscope::gui::plot {

// What a plot window keeps from one frame to the next; the panel that shows the figure owns it (in the
// app's PanelState, so opening a scene starts it afresh). Every member has an initializer, so a panel
// can give just some: {.exportPath = "angular-plot.csv"}.
struct PlotWindowState {
    bool open = false;
    std::vector<Scale> scales{};  // per sub-plot as the user set it; sub-plots past its end start at defaultScale
    // The y labels of the sub-plots `scales` belongs to: a figure with other sub-plots (a trace with
    // wavelength bands after one without) starts every sub-plot at its defaultScale again.
    std::vector<std::string> scaledSubPlots{};
    bool grid = true;                  // grid lines at the major ticks
    std::optional<AxisRange> xView{};  // the x range zoomed to; none: the whole axis
    std::string exportPath{};          // the CSV export's file name field
    std::optional<Readout> hovered{};  // the readout shown in the last frame, while the mouse is over a sub-plot
};

}  // namespace dropscope::gui::plot
