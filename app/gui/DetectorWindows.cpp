#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/TraceActions.hpp"
#include "render/Colour.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace dropscope::gui {

namespace {

constexpr int kMaxCells = 256;           // cells drawn per axis at most; a larger image is drawn in blocks
constexpr double kLogDecades = 4.0;      // the log scale's range below the brightest pixel
constexpr int kBarSteps = 48;            // bands of the colour bar
constexpr float kBarWidth = 14.0f;       // the colour bar's ramp
constexpr float kBarLabelWidth = 64.0f;  // beside it, its numbers
constexpr float kBinningWidth = 50.0f;
constexpr float kWindowWidth = 460.0f;
constexpr float kWindowHeight = 520.0f;
constexpr float kCascade = 24.0f;                        // between the first places of consecutive detectors' windows
const ImU32 kOutsideColour = IM_COL32(45, 45, 48, 255);  // a far-field pixel outside the projection's domain

ImU32 viridisColour(double t) {
    const render::Colour c = render::viridis(t);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1.0f));
}

// Where `value` sits on the colour scale, 0 to 1.
double scaleOf(double value, double max, bool log) {
    if (!(max > 0.0) || !(value > 0.0)) return 0.0;
    if (!log) return std::clamp(value / max, 0.0, 1.0);
    return std::clamp(1.0 + std::log10(value / max) / kLogDecades, 0.0, 1.0);
}

// The value at scale position t (the colour bar's labels).
double valueAt(double t, double max, bool log) { return log ? max * std::pow(10.0, (t - 1.0) * kLogDecades) : t * max; }

constexpr std::array<const char*, 4> kBinnings{"1", "2", "4", "8"};  // DetectorView::binning's choices

// The colour of the block of step x step pixels from (ix, iy): the mean of its pixels' sky colours (sRGB
// averaged as it is), or its pixels' mean density on viridis; the outside colour when no pixel is in the view.
ImU32 blockColour(const DetectorImage& image, int ix, int iy, int step, const DetectorView& view, bool trueColour) {
    const PixelGrid& grid = image.detector.pixels;
    std::array<double, 3> rgb{};
    double density = 0.0;
    int inside = 0;
    for (int y = iy; y < std::min(iy + step, grid.ny); ++y) {
        for (int x = ix; x < std::min(ix + step, grid.nx); ++x) {
            const std::size_t k = grid.index(x, y);
            if (!std::isfinite(image.density[k])) continue;
            ++inside;
            density += image.density[k];
            if (trueColour) {
                for (std::size_t c = 0; c < 3; ++c) rgb[c] += image.sky[3 * k + c];
            }
        }
    }
    if (inside == 0) return kOutsideColour;
    if (!trueColour) return viridisColour(scaleOf(density / inside, image.maxDensity, view.logScale));
    const auto mean = [&](std::size_t c) { return static_cast<int>(std::lround(rgb[c] / inside)); };
    return IM_COL32(mean(0), mean(1), mean(2), 255);
}

// The image in `size` at `at`, one filled rectangle per pixel, or per block of the view's binning (at least as
// many as keep it to kMaxCells a side).
void drawPixels(ImDrawList* draw, const DetectorImage& image, const DetectorView& view, bool trueColour, ImVec2 at,
                ImVec2 size) {
    const PixelGrid& grid = image.detector.pixels;
    const int step = std::max(view.binning, (std::max(grid.nx, grid.ny) + kMaxCells - 1) / kMaxCells);
    const float cellW = size.x / static_cast<float>(grid.nx);
    const float cellH = size.y / static_cast<float>(grid.ny);
    draw->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), trueColour ? IM_COL32_BLACK : viridisColour(0.0));
    for (int iy = 0; iy < grid.ny; iy += step) {
        for (int ix = 0; ix < grid.nx; ix += step) {
            const ImU32 colour = blockColour(image, ix, iy, step, view, trueColour);
            const float x = at.x + cellW * static_cast<float>(ix);
            const float y = at.y + cellH * static_cast<float>(grid.ny - std::min(iy + step, grid.ny));
            const float w = cellW * static_cast<float>(std::min(step, grid.nx - ix));
            const float h = cellH * static_cast<float>(std::min(step, grid.ny - iy));
            draw->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), colour);
        }
    }
}

// The colour bar beside the image, its top at the brightest pixel's density, with five numbers.
void drawColourBar(ImDrawList* draw, const DetectorImage& image, const DetectorView& view, ImVec2 at, float height) {
    const float band = height / kBarSteps;
    for (int k = 0; k < kBarSteps; ++k) {
        const float y = at.y + height - band * static_cast<float>(k + 1);
        draw->AddRectFilled(ImVec2(at.x, y), ImVec2(at.x + kBarWidth, y + band), viridisColour((k + 0.5) / kBarSteps));
    }
    const float lineHeight = ImGui::GetTextLineHeight();
    for (int tick = 0; tick <= 4; ++tick) {
        const double t = tick / 4.0;
        const float y = at.y + height * static_cast<float>(1.0 - t);
        char label[32];
        std::snprintf(label, sizeof label, "%.3g", valueAt(t, image.maxDensity, view.logScale));
        draw->AddLine(ImVec2(at.x + kBarWidth, y), ImVec2(at.x + kBarWidth + 4.0f, y), IM_COL32_WHITE);
        const float textY = std::clamp(y - 0.5f * lineHeight, at.y - 0.5f * lineHeight, at.y + height - lineHeight);
        draw->AddText(ImVec2(at.x + kBarWidth + 6.0f, textY), IM_COL32_WHITE, label);
    }
}

// "pixel (12, 40): u 0.31, v -0.02; fraction 1.2e-4, irradiance 0.031 /unit^2", under the mouse.
std::string readout(const DetectorImage& image, int ix, int iy) {
    const std::size_t k = image.detector.pixels.index(ix, iy);
    const bool farField = image.detector.type == DetectorType::FarField;
    char text[200];
    std::snprintf(text, sizeof text, "pixel (%d, %d): %s %.4g%s, %s %.4g%s\nfraction %.4g, %s %.4g %s", ix, iy,
                  farField ? "theta" : "u", image.where[k][0], farField ? " deg" : "", farField ? "azimuth" : "v",
                  image.where[k][1], farField ? " deg" : "", image.fraction[k], densityName(image.detector),
                  image.density[k], densityUnit(image.detector));
    return text;
}

void drawImageWindow(DetectorView& view, int cascade, const ShownTallies& shown, const ItemProbe& probe) {
    DetectorImage& image = *view.image;
    const Detector& detector = image.detector;
    const PixelGrid& grid = detector.pixels;
    const std::string title = "Detector " + detector.name;
    // Over the 3D view, between the panel columns; each detector's a little lower and to the right.
    const float offset = kCascade * static_cast<float>(cascade);
    ImGui::SetNextWindowPos(ImVec2(kPanelWidth + 10.0f + offset, kMenuHeight + 10.0f + offset), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kWindowWidth, kWindowHeight), ImGuiCond_FirstUseEver);
    if (std::exchange(view.focus, false)) ImGui::SetNextWindowFocus();
    if (!ImGui::Begin(title.c_str(), &view.open)) return ImGui::End();
    const std::string what =
        std::string(detectorTypeName(detector.type)) + " " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny);
    const double share = image.photons > 0 ? static_cast<double>(image.hits) / static_cast<double>(image.photons) : 0.0;
    ImGui::Text("%s; %llu hits, %.4g of %llu photons%s", what.c_str(), static_cast<unsigned long long>(image.hits),
                share, static_cast<unsigned long long>(image.photons), shown.filling ? " (filling in)" : "");
    const bool sky = !image.sky.empty();
    if (sky) {
        ImGui::Checkbox("false colour (radiance)", &view.falseColour);
        ImGui::SameLine();
    }
    const bool trueColour = sky && !view.falseColour;
    if (!trueColour) {
        ImGui::Checkbox("log scale", &view.logScale);
        ImGui::SameLine();
    }
    int binning = std::countr_zero(static_cast<unsigned>(view.binning));
    ImGui::SetNextItemWidth(kBinningWidth);
    if (choiceCombo("binning", binning, kBinnings, probe,
                    "draws blocks of 2 x 2 pixels or more, each the mean of its pixels:\na smoother image of "
                    "fewer photons (the readout stays per pixel)")) {
        view.binning = 1 << binning;
    }

    // The image keeps the detector's proportions: its size (plane) or square pixels (far field).
    const double width = detector.type == DetectorType::Plane ? detector.size[0] : grid.nx;
    const double height = detector.type == DetectorType::Plane ? detector.size[1] : grid.ny;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float roomX = std::max(avail.x - kBarWidth - kBarLabelWidth, 32.0f);
    const float roomY = std::max(avail.y - 2.5f * ImGui::GetTextLineHeightWithSpacing(), 32.0f);
    const auto scale = static_cast<float>(std::min(roomX / width, roomY / height));
    const ImVec2 size(scale * static_cast<float>(width), scale * static_cast<float>(height));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("image", size);  // the image takes the mouse: no window drag from it
    reportItemRect(probe, "detector " + detector.name + " image");
    const bool hovered = ImGui::IsItemHovered();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    drawPixels(draw, image, view, trueColour, at, size);
    if (!trueColour) drawColourBar(draw, image, view, ImVec2(at.x + size.x + 6.0f, at.y), size.y);

    std::string text = std::string("hover the image: a pixel's ") + densityName(detector);
    if (hovered) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const int ix =
            std::clamp(static_cast<int>((mouse.x - at.x) / size.x * static_cast<float>(grid.nx)), 0, grid.nx - 1);
        const int iy = std::clamp(static_cast<int>((at.y + size.y - mouse.y) / size.y * static_cast<float>(grid.ny)), 0,
                                  grid.ny - 1);
        text = readout(image, ix, iy);
    }
    probedText(probe, "detector " + detector.name + " readout", text);
    ImGui::End();
}

}  // namespace

void drawDetectorWindows(TraceState& traces, const ItemProbe& probe) {
    const ShownTallies shown = shownTallies(traces);
    if (!shown.tallies) return;
    int cascade = 0;
    for (const DetectorTally* tally : shown.tallies->all<DetectorTally>()) {
        ++cascade;
        const auto found = traces.views.detectors.find(tally->detector().name);
        if (found == traces.views.detectors.end() || !found->second.open) continue;
        DetectorView& view = found->second;
        if (view.builtFor != traces.talliesId || !view.image || view.image->detector.name != tally->detector().name) {
            view.image = detectorImage(*tally);
            view.builtFor = traces.talliesId;
        }
        if (view.image) drawImageWindow(view, cascade - 1, shown, probe);
    }
}

}  // namespace dropscope::gui
