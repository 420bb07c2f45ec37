#pragma once

#include "gui/ItemProbe.hpp"
#include "gui/StatusLine.hpp"
#include "gui/plot/PlotData.hpp"
#include "gui/plot/PlotWindowState.hpp"

namespace dropscope::gui {

// Draws `figure` in its own resizable window while state.open (its close button clears that): the
// sub-plots stacked over the shared x axis, each with its y label, log switch and legend; ticks, grid,
// a readout of the samples under the mouse (state.hovered); zoom of x by wheel or drag, double-click
// for the whole axis; CSV export of every sample to state.exportPath, reported in `status`. Tells
// `probe` where it drew "<title> frame <i>" (sub-plot i's frame) and "<title> export" (the button).
void drawPlotWindow(const plot::Figure& figure, plot::PlotWindowState& state, StatusLine& status,
                    const ItemProbe& probe = {});

}  // namespace dropscope::gui
