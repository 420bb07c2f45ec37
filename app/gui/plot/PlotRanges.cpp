#include "gui/plot/PlotRanges.hpp"

#include "gui/plot/PlotAxes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope::gui::plot {

namespace {

// A y axis leaves this fraction of its span free above and below the data, so no curve runs along the frame.
constexpr double kYMargin = 0.05;
// An extent narrower than this, relative to its values, is a single value: its ticks would need more
// digits than a double has.
constexpr double kSingleValueResolution = 1e-12;
// A single value v is shown over v -/+ this fraction of |v| (linear axis).
constexpr double kSingleValueHalfWidth = 0.5;
const double kHalfDecade = std::sqrt(10.0);

void extend(std::optional<AxisRange>& extent, double value) {
    if (!extent) {
        extent = AxisRange{value, value};
    } else {
        extent->lo = std::min(extent->lo, value);
        extent->hi = std::max(extent->hi, value);
    }
}

bool singleValue(AxisRange extent) {
    return extent.span() <= kSingleValueResolution * std::max(std::abs(extent.lo), std::abs(extent.hi));
}

}  // namespace

std::optional<AxisRange> xExtent(const Figure& figure) {
    std::optional<AxisRange> extent;
    for (const SubPlot& subPlot : figure.subPlots) {
        for (const Curve& curve : subPlot.curves) {
            for (std::size_t i = 0; i < sampleCount(curve); ++i) {
                if (std::isfinite(curve.x[i])) extend(extent, curve.x[i]);
            }
        }
    }
    return extent;
}

bool anyDrawable(const Curve& curve, Scale scale) {
    for (std::size_t i = 0; i < sampleCount(curve); ++i) {
        if (std::isfinite(curve.x[i]) && drawable(curve.y[i], scale)) return true;
    }
    return false;
}

std::optional<AxisRange> yExtent(const SubPlot& subPlot, Scale scale, AxisRange xView) {
    std::optional<AxisRange> extent;
    for (const Curve& curve : subPlot.curves) {
        for (std::size_t i = 0; i < sampleCount(curve); ++i) {
            if (curve.x[i] >= xView.lo && curve.x[i] <= xView.hi && drawable(curve.y[i], scale)) {
                extend(extent, curve.y[i]);
            }
        }
    }
    return extent;
}

AxisRange fittedRange(std::optional<AxisRange> extent, Scale scale, double margin) {
    if (!extent) return scale == Scale::Log ? AxisRange{1.0, 10.0} : AxisRange{0.0, 1.0};
    const AxisRange e = *extent;
    if (scale == Scale::Log) {
        if (singleValue(e)) return {e.lo / kHalfDecade, e.hi * kHalfDecade};
        // In decades (hi / lo may overflow), and no further than the doubles go: a log axis stays positive
        // and finite.
        const double widen = std::pow(10.0, margin * (std::log10(e.hi) - std::log10(e.lo)));
        return {std::max(e.lo / widen, std::numeric_limits<double>::min()),
                std::min(e.hi * widen, std::numeric_limits<double>::max())};
    }
    if (singleValue(e)) {
        const double halfWidth = e.lo == 0.0 && e.hi == 0.0 ? 1.0 : kSingleValueHalfWidth * std::abs(e.hi);
        return {e.lo - halfWidth, e.hi + halfWidth};
    }
    return {e.lo - margin * e.span(), e.hi + margin * e.span()};
}

AxisRange fullXRange(const Figure& figure) {
    if (figure.xRange && std::isfinite(figure.xRange->lo) && std::isfinite(figure.xRange->hi) &&
        figure.xRange->lo < figure.xRange->hi) {
        return *figure.xRange;
    }
    return fittedRange(xExtent(figure), Scale::Linear, 0.0);
}

AxisRange yAxisRange(const SubPlot& subPlot, Scale scale, AxisRange xView) {
    const std::optional<AxisRange>& fixed = subPlot.yRange;
    if (fixed && fixed->lo < fixed->hi && drawable(fixed->lo, scale) && drawable(fixed->hi, scale)) return *fixed;
    return fittedRange(yExtent(subPlot, scale, xView), scale, kYMargin);
}

AxisRange clampedView(AxisRange wanted, AxisRange full) {
    if (!std::isfinite(wanted.lo) || !std::isfinite(wanted.hi)) return full;
    const double width = std::max(std::abs(wanted.span()), kMinViewFraction * full.span());
    if (width >= full.span()) return full;
    const double lo = std::clamp(std::min(wanted.lo, wanted.hi), full.lo, full.hi - width);
    return {lo, lo + width};
}

AxisRange zoomedAbout(AxisRange view, AxisRange full, double anchor, double factor) {
    return clampedView({anchor - (anchor - view.lo) * factor, anchor + (view.hi - anchor) * factor}, full);
}

}  // namespace dropscope::gui::plot
