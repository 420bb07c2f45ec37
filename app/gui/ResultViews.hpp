#pragma once

#include "gui/DetectorImage.hpp"
#include "gui/PathFilter.hpp"
#include "gui/plot/PlotWindowState.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace dropscope::gui {

// One detector's image window (DetectorWindows.cpp): open or not, how it shows the image, and the image made
// from the tallies numbered `builtFor` (TraceState::talliesId), made again when they move on.
struct DetectorView {
    bool open = false;
    bool focus = false;        // brought to the front in the next frame (its button was pressed)
    bool falseColour = false;  // far field: radiance in viridis instead of the sky in true colour
    bool logScale = false;     // the false colours over four decades below the brightest pixel
    int binning = 1;           // pixels a side drawn as one block, their mean (a noisy image of few photons)
    std::uint64_t builtFor = 0;
    std::optional<DetectorImage> image;
};

// How the results of the traces are viewed besides the Results panel's own numbers: the detector windows (by
// detector name), the ray orders' plot window and the energy budget's.
struct ResultViews {
    std::map<std::string, DetectorView> detectors;
    plot::PlotWindowState ordersPlot{.exportPath = "orders-plot.csv"};
    bool budgetOpen = false;  // the Energy budget window
};

}  // namespace dropscope::gui
