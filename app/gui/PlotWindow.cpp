#include "gui/PlotWindow.hpp"

#include "gui/PanelWidgets.hpp"
#include "gui/plot/PlotAxes.hpp"
#include "gui/plot/PlotCsv.hpp"
#include "gui/plot/PlotRanges.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace dropscope::gui {

using plot::AxisMapping;
using plot::AxisRange;
using plot::Curve;
using plot::Figure;
using plot::PlotWindowState;
using plot::Scale;
using plot::SubPlot;
using plot::Tick;

namespace {

constexpr float kDefaultWidth = 620.0f;  // the window when first opened
constexpr float kDefaultHeight = 440.0f;
constexpr float kMinFrameHeight = 60.0f;  // smaller, a frame has room for two y ticks at most
constexpr float kTickLength = 6.0f;
constexpr float kMinorTickLength = 3.0f;
constexpr float kLabelPad = 4.0f;      // between a tick label and the frame
constexpr float kRightMargin = 24.0f;  // room for the half of the last x label that lies past the frame
constexpr float kSwatchWidth = 16.0f;  // a legend entry's line
constexpr float kSwatchThickness = 3.0f;
constexpr float kLineThickness = 1.5f;
constexpr float kSampleMarkRadius = 3.0f;  // a curve of one point; the readout rings its samples a pixel wider
constexpr float kRingThickness = 2.0f;
// Tick labels keep this many text heights apart: x labels two (0, 20, ..., 180 at the default size, no
// denser), y labels one.
constexpr float kXLabelGapLines = 2.0f;
constexpr float kYLabelGapLines = 1.0f;
constexpr float kFileFieldWidth = 220.0f;  // the export's file name, at most this wide
constexpr float kMinDragPixels = 4.0f;     // a shorter drag is a click, not a zoom
constexpr double kWheelZoom = 0.8;         // one wheel line in shows 80% of the x range, one out 125%
// Points are clamped this far beyond the frame: floats keep sub-pixel steps out to there, and ImGui
// never sees an infinity (a value of 1e300 on a linear axis).
constexpr float kPixelReach = 1e7f;
constexpr float kGridAlpha = 0.15f;
constexpr float kSelectionAlpha = 0.2f;
// Okabe and Ito's colour-blind-safe colours, ordered to stay apart on the dark background.
const std::array<ImU32, 7> kPalette{
    IM_COL32(86, 180, 233, 255),  IM_COL32(230, 159, 0, 255),  IM_COL32(0, 158, 115, 255), IM_COL32(213, 94, 0, 255),
    IM_COL32(204, 121, 167, 255), IM_COL32(240, 228, 66, 255), IM_COL32(0, 114, 178, 255)};

// A curve's own colour, else the palette's by its place in the sub-plot.
ImU32 curveColour(const SubPlot& subPlot, std::size_t index) {
    if (const auto& colour = subPlot.curves[index].colour) {
        return ImGui::ColorConvertFloat4ToU32(ImVec4((*colour)[0], (*colour)[1], (*colour)[2], 1.0f));
    }
    return kPalette[index % kPalette.size()];
}

// One sub-plot's frame in screen pixels and its y axis.
struct FrameLayout {
    ImVec2 min;
    ImVec2 max;
    AxisMapping y;
    std::vector<Tick> yTicks;
};

// Where everything goes this frame: the shared x axis and each sub-plot's frame.
struct Layout {
    AxisRange full;  // the whole x axis
    AxisRange view;  // the part shown
    AxisMapping x;
    std::vector<Tick> xTicks;
    std::vector<FrameLayout> frames;
    float left = 0.0f;          // the content region's left edge (y labels start here)
    float headerHeight = 0.0f;  // the y label, log switch and legend above each frame
};

float textWidth(const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; }

void setView(PlotWindowState& state, AxisRange wanted, AxisRange full) {
    const AxisRange view = plot::clampedView(wanted, full);
    state.xView = view == full ? std::nullopt : std::optional<AxisRange>(view);
}

Layout layoutFrames(const Figure& figure, const PlotWindowState& state) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const float line = ImGui::GetTextLineHeight();
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float xAxisHeight = kLabelPad + 2.0f * line + spacing;  // tick labels, then the x label
    const auto count = static_cast<float>(figure.subPlots.size());
    Layout layout;
    layout.left = origin.x;
    layout.headerHeight = ImGui::GetFrameHeightWithSpacing();
    const float frameHeight =
        std::max(kMinFrameHeight, (available.y - count * (layout.headerHeight + spacing) - xAxisHeight) / count);
    layout.full = plot::fullXRange(figure);
    layout.view = state.xView ? plot::clampedView(*state.xView, layout.full) : layout.full;
    // The y axes first: the widest y label sets where every frame starts, so that the frames line up.
    float labelWidth = 0.0f;
    float top = origin.y;
    for (std::size_t i = 0; i < figure.subPlots.size(); ++i) {
        top += layout.headerHeight;
        const Scale scale = state.scales[i];
        FrameLayout frame{{0.0f, top}, {0.0f, top + frameHeight}, {}, {}};
        frame.y = AxisMapping{plot::yAxisRange(figure.subPlots[i], scale, layout.view), scale, top + frameHeight, top};
        frame.yTicks = plot::fittedTicks(
            frame.y, [&](const std::string&) { return line; }, kYLabelGapLines * line);
        for (const Tick& tick : frame.yTicks) labelWidth = std::max(labelWidth, textWidth(tick.label));
        layout.frames.push_back(std::move(frame));
        top += frameHeight + spacing;
    }
    const float left = origin.x + labelWidth + kLabelPad;
    const float right = std::max(left + 1.0f, origin.x + available.x - kRightMargin);
    for (FrameLayout& frame : layout.frames) {
        frame.min.x = left;
        frame.max.x = right;
    }
    layout.x = AxisMapping{layout.view, Scale::Linear, left, right};
    layout.xTicks = plot::fittedTicks(
        layout.x, [](const std::string& label) { return textWidth(label); }, kXLabelGapLines * line);
    return layout;
}

// The y label, the log switch and the legend (a line of each curve's colour and its name), on one row.
void drawHeader(const SubPlot& subPlot, Scale& scale) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(subPlot.yLabel.c_str());
    ImGui::SameLine();
    bool log = scale == Scale::Log;
    if (ImGui::Checkbox("log", &log)) scale = log ? Scale::Log : Scale::Linear;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (std::size_t k = 0; k < subPlot.curves.size(); ++k) {
        const Curve& curve = subPlot.curves[k];
        ImGui::SameLine();
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float middle = at.y + 0.5f * ImGui::GetFrameHeight();
        ImGui::Dummy(ImVec2(kSwatchWidth, ImGui::GetFrameHeight()));
        draw->AddLine(ImVec2(at.x, middle), ImVec2(at.x + kSwatchWidth, middle), curveColour(subPlot, k),
                      kSwatchThickness);
        ImGui::SameLine();
        ImGui::TextUnformatted(curve.name.c_str());
        if (!plot::anyDrawable(curve, scale)) {
            ImGui::SameLine();
            ImGui::TextDisabled(scale == Scale::Log ? "(no value > 0: none on a log axis)" : "(no finite value)");
        }
    }
}

ImVec2 clampedPoint(double x, double y, const FrameLayout& frame) {
    return ImVec2(std::clamp(static_cast<float>(x), frame.min.x - kPixelReach, frame.max.x + kPixelReach),
                  std::clamp(static_cast<float>(y), frame.min.y - kPixelReach, frame.max.y + kPixelReach));
}

void flushRun(ImDrawList* draw, std::vector<ImVec2>& run, ImU32 colour) {
    if (run.size() == 1) draw->AddCircleFilled(run.front(), kSampleMarkRadius, colour);
    if (run.size() > 1) draw->AddPolyline(run.data(), static_cast<int>(run.size()), colour, 0, kLineThickness);
    run.clear();
}

// A curve as lines between its drawable samples (a gap where one is not), from the sample before the
// x range shown to the one after it.
void drawCurve(ImDrawList* draw, const Curve& curve, ImU32 colour, const AxisMapping& x, const FrameLayout& frame) {
    const std::size_t count = plot::sampleCount(curve);
    const auto xs = curve.x.begin();
    const auto end = xs + static_cast<std::ptrdiff_t>(count);
    const auto first =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, std::lower_bound(xs, end, x.range.lo) - xs - 1));
    const auto last = static_cast<std::size_t>(std::upper_bound(xs, end, x.range.hi) - xs);
    std::vector<ImVec2> run;
    for (std::size_t i = first; i < std::min(last + 1, count); ++i) {
        const double px = x.toPixel(curve.x[i]);
        const double py = frame.y.toPixel(curve.y[i]);
        if (std::isfinite(px) && std::isfinite(py)) {
            run.push_back(clampedPoint(px, py, frame));
        } else {
            flushRun(draw, run, colour);
        }
    }
    flushRun(draw, run, colour);
}

// The frame, its grid and ticks, the y labels, the curves, and the x labels under the bottom one.
void drawFrame(const SubPlot& subPlot, const FrameLayout& frame, const Layout& layout, bool grid, bool xLabels) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 gridColour = ImGui::GetColorU32(ImGuiCol_Text, kGridAlpha);
    const float line = ImGui::GetTextLineHeight();
    draw->AddRectFilled(frame.min, frame.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
    for (const Tick& tick : layout.xTicks) {
        const auto px = static_cast<float>(layout.x.toPixel(tick.value));
        if (grid && tick.major) draw->AddLine(ImVec2(px, frame.min.y), ImVec2(px, frame.max.y), gridColour);
        draw->AddLine(ImVec2(px, frame.max.y), ImVec2(px, frame.max.y - (tick.major ? kTickLength : kMinorTickLength)),
                      text);
        if (!xLabels || !tick.major) continue;
        const float left = std::clamp(px - 0.5f * textWidth(tick.label), layout.left, frame.max.x + kRightMargin);
        draw->AddText(ImVec2(left, frame.max.y + kLabelPad), text, tick.label.c_str());
    }
    for (const Tick& tick : frame.yTicks) {
        const auto py = static_cast<float>(frame.y.toPixel(tick.value));
        if (grid && tick.major) draw->AddLine(ImVec2(frame.min.x, py), ImVec2(frame.max.x, py), gridColour);
        draw->AddLine(ImVec2(frame.min.x, py), ImVec2(frame.min.x + (tick.major ? kTickLength : kMinorTickLength), py),
                      text);
        if (!tick.major) continue;
        // Kept within the frame's height, so the lowest label never runs into the x labels below.
        const float top = std::clamp(py - 0.5f * line, frame.min.y - 0.5f * line, frame.max.y - line);
        draw->AddText(ImVec2(frame.min.x - kLabelPad - textWidth(tick.label), top), text, tick.label.c_str());
    }
    draw->PushClipRect(frame.min, frame.max, true);
    for (std::size_t k = 0; k < subPlot.curves.size(); ++k) {
        drawCurve(draw, subPlot.curves[k], curveColour(subPlot, k), layout.x, frame);
    }
    draw->PopClipRect();
    draw->AddRect(frame.min, frame.max, text);
}

// Wheel: zoom about the mouse; drag: zoom to the x range dragged over; double-click: the whole axis.
// Hovering, not dragging: the readout.
void handleMouse(const Figure& figure, std::size_t index, const Layout& layout, PlotWindowState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemDeactivated() && std::abs(io.MousePos.x - io.MouseClickedPos[0].x) >= kMinDragPixels) {
        setView(state, {layout.x.toValue(io.MouseClickedPos[0].x), layout.x.toValue(io.MousePos.x)}, layout.full);
    }
    if (!ImGui::IsItemHovered()) return;
    const double x = layout.x.toValue(io.MousePos.x);
    if (io.MouseWheel != 0.0f) {
        setView(state, plot::zoomedAbout(layout.view, layout.full, x, std::pow(kWheelZoom, io.MouseWheel)),
                layout.full);
    }
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) state.xView.reset();
    if (!ImGui::IsItemActive()) state.hovered = plot::readoutAt(figure.subPlots[index], index, x);
}

// Over every frame: the x range being dragged over, or the cursor line and the readout's samples.
void drawCursor(const Figure& figure, const Layout& layout, const PlotWindowState& state, bool dragging) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    for (const FrameLayout& frame : layout.frames) {
        if (dragging) {
            const float from = std::clamp(io.MouseClickedPos[0].x, frame.min.x, frame.max.x);
            const float to = std::clamp(io.MousePos.x, frame.min.x, frame.max.x);
            draw->AddRectFilled(ImVec2(std::min(from, to), frame.min.y), ImVec2(std::max(from, to), frame.max.y),
                                ImGui::GetColorU32(ImGuiCol_Text, kSelectionAlpha));
        } else if (state.hovered) {
            draw->AddLine(ImVec2(io.MousePos.x, frame.min.y), ImVec2(io.MousePos.x, frame.max.y),
                          ImGui::GetColorU32(ImGuiCol_Text));
        }
    }
    if (dragging || !state.hovered) return;
    const FrameLayout& frame = layout.frames[state.hovered->subPlot];
    for (const plot::CurveSample& sample : state.hovered->samples) {
        const double px = layout.x.toPixel(sample.x);
        const double py = frame.y.toPixel(sample.y);
        if (std::isfinite(px) && std::isfinite(py)) {
            draw->AddCircle(clampedPoint(px, py, frame), kSampleMarkRadius + 1.0f,
                            curveColour(figure.subPlots[state.hovered->subPlot], sample.curve), 0, kRingThickness);
        }
    }
}

void drawReadoutTooltip(const Figure& figure, const plot::Readout& readout) {
    const std::vector<std::string> lines = plot::readoutLines(readout, figure.xLabel);
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(lines.front().c_str());
    for (std::size_t k = 1; k < lines.size(); ++k) {
        ImGui::PushStyleColor(ImGuiCol_Text,
                              curveColour(figure.subPlots[readout.subPlot], readout.samples[k - 1].curve));
        ImGui::TextUnformatted(lines[k].c_str());
        ImGui::PopStyleColor();
    }
    ImGui::EndTooltip();
}

void drawSubPlots(const Figure& figure, PlotWindowState& state, const ItemProbe& probe) {
    const Layout layout = layoutFrames(figure, state);
    bool dragging = false;
    for (std::size_t i = 0; i < figure.subPlots.size(); ++i) {
        const FrameLayout& frame = layout.frames[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::SetCursorScreenPos(ImVec2(layout.left, frame.min.y - layout.headerHeight));
        drawHeader(figure.subPlots[i], state.scales[i]);
        ImGui::SetCursorScreenPos(frame.min);
        ImGui::InvisibleButton("frame", ImVec2(frame.max.x - frame.min.x, frame.max.y - frame.min.y));
        reportItemRect(probe, figure.title + " frame " + std::to_string(i));
        handleMouse(figure, i, layout, state);
        dragging = dragging || (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left));
        drawFrame(figure.subPlots[i], frame, layout, state.grid, i + 1 == figure.subPlots.size());
        ImGui::PopID();
    }
    drawCursor(figure, layout, state, dragging);
    const FrameLayout& bottom = layout.frames.back();
    const float line = ImGui::GetTextLineHeight();
    const float middle = 0.5f * (bottom.min.x + bottom.max.x);
    ImGui::SetCursorScreenPos(ImVec2(middle - 0.5f * textWidth(figure.xLabel), bottom.max.y + kLabelPad + line));
    ImGui::TextUnformatted(figure.xLabel.c_str());
    if (state.hovered && !dragging) drawReadoutTooltip(figure, *state.hovered);
}

void exportCsv(const Figure& figure, const std::string& path, StatusLine& status) {
    if (path.empty()) {
        status.refuse("plot not exported: no file name");
        return;
    }
    status.attempt("plot not exported", [&] {
        plot::writePlotCsv(figure, path);
        status.say("exported " + std::to_string(plot::plotCsvRows(figure)) + " rows of the " + figure.title +
                   " plot to " + path);
    });
}

// Export, its file name, the grid switch, and how to zoom (or a button back to the whole axis).
void drawToolbar(const Figure& figure, PlotWindowState& state, StatusLine& status, const ItemProbe& probe) {
    if (ImGui::Button("Export CSV")) exportCsv(figure, state.exportPath, status);
    reportItemRect(probe, figure.title + " export");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::min(kFileFieldWidth, 0.4f * ImGui::GetContentRegionAvail().x));
    ImGui::InputText("##file", &state.exportPath);
    ImGui::SameLine();
    ImGui::Checkbox("grid", &state.grid);
    ImGui::SameLine();
    if (state.xView) {
        if (ImGui::Button("whole x axis")) state.xView.reset();
    } else {
        ImGui::TextDisabled("zoom x: wheel or drag");
    }
}

}  // namespace

void drawPlotWindow(const Figure& figure, PlotWindowState& state, StatusLine& status, const ItemProbe& probe) {
    state.hovered.reset();
    if (!state.open) return;
    std::vector<std::string> labels;
    for (const SubPlot& subPlot : figure.subPlots) labels.push_back(subPlot.yLabel);
    if (labels != state.scaledSubPlots) {
        state.scales.clear();
        state.scaledSubPlots = std::move(labels);
    }
    for (std::size_t i = state.scales.size(); i < figure.subPlots.size(); ++i) {
        state.scales.push_back(figure.subPlots[i].defaultScale);
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(kDefaultWidth, kDefaultHeight), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(1.0f);  // the 3D view showing through would read as data
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    if (ImGui::Begin(figure.title.c_str(), &state.open, flags)) {
        drawToolbar(figure, state, status, probe);
        if (figure.subPlots.empty()) {
            ImGui::TextDisabled("nothing to plot");
        } else {
            drawSubPlots(figure, state, probe);
        }
    }
    ImGui::End();
}

}  // namespace dropscope::gui
