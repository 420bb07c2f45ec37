#pragma once

#include "gui/plot/PlotData.hpp"

#include <optional>

// Which part of the data a plot's axes span: fitted to the data, fixed by the figure, or zoomed.
namespace dropscope::gui::plot {

// The x extent of every curve's samples (finite x only); none without any.
std::optional<AxisRange> xExtent(const Figure& figure);
// Whether any sample of the curve can be drawn on `scale` (a finite x, and a y finite and, on a log axis,
// positive): the legend says so when none can.
bool anyDrawable(const Curve& curve, Scale scale);

// The extent of a sub-plot's y values drawable on `scale` (NaN skipped, and values <= 0 on a log axis)
// at x within `xView`; none when there are none.
std::optional<AxisRange> yExtent(const SubPlot& subPlot, Scale scale, AxisRange xView);

// The axis that shows data of this extent: widened by `margin` of its span on each side (of its span
// in log10 on a log axis); a single value (or one within rounding of it) widened to half its size on
// each side (a decade around it on a log axis, [-1, 1] for zero); no data: [0, 1], [1, 10] on a log axis.
AxisRange fittedRange(std::optional<AxisRange> extent, Scale scale, double margin);

// The whole x axis of a figure: its xRange, else its data's extent.
AxisRange fullXRange(const Figure& figure);
// A sub-plot's y axis over the x range shown: its yRange when it suits the scale (positive on a log
// axis), else fitted to its data with a small margin.
AxisRange yAxisRange(const SubPlot& subPlot, Scale scale, AxisRange xView);

// `wanted` (its ends in either order) moved and narrowed to lie within `full`, and no narrower than
// kMinViewFraction of it; `full` itself when `wanted` is not finite.
AxisRange clampedView(AxisRange wanted, AxisRange full);
// `view` scaled by `factor` about `anchor` (factor < 1 zooms in, anchor stays where it is), within `full`.
AxisRange zoomedAbout(AxisRange view, AxisRange full, double anchor, double factor);

// Zooming stops at a millionth of the whole axis: closer, the samples of any data we plot are far apart
// and the tick steps near the resolution of the axis's values.
inline constexpr double kMinViewFraction = 1e-6;

}  // namespace dropscope::gui::plot
