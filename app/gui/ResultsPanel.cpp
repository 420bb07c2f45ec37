#include "gui/PanelLayout.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace dropscope::gui {

namespace {

// Escapes per steradian in each angular bin, as a fraction of the photons traced: angular.csv's
// fraction_per_sr, the quantity whose peaks are the rainbows.
std::vector<float> perSteradian(const TraceTally& tally) {
    const std::size_t bins = tally.angular.size();
    std::vector<float> values(bins, 0.0f);
    if (tally.photons == 0) return values;
    const double width = std::numbers::pi / static_cast<double>(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        const double solidAngle =
            2.0 * std::numbers::pi *
            (std::cos(width * static_cast<double>(k)) - std::cos(width * static_cast<double>(k + 1)));
        values[k] =
            static_cast<float>(static_cast<double>(tally.angular[k]) / static_cast<double>(tally.photons) / solidAngle);
    }
    return values;
}

}  // namespace

void drawResultsPanel(const TraceState& traces, bool& logScale) {
    placeNextPanel(PanelSide::Left, 0.79f, 0.21f);
    if (!ImGui::Begin("Results")) {
        ImGui::End();
        return;
    }
    if (!traces.trace) {
        ImGui::TextDisabled("no trace yet: fire photons (Space)");
        ImGui::End();
        return;
    }
    const TraceResult& result = traces.trace->outcome.result;
    const TraceTally& tally = result.tally;
    const double n = tally.photons > 0 ? static_cast<double>(tally.photons) : 1.0;
    ImGui::Text("%llu photons%s, %.2f s", static_cast<unsigned long long>(tally.photons),
                result.partial ? " (stopped early)" : "", result.seconds);
    ImGui::Text("escaped %.5f  absorbed %.5f", static_cast<double>(tally.escaped) / n,
                static_cast<double>(tally.absorbed) / n);
    ImGui::Text("lost %.5f  unscattered %.5f", static_cast<double>(tally.lost) / n,
                static_cast<double>(tally.unscattered) / n);
    ImGui::Checkbox("log scale", &logScale);
    std::vector<float> values = perSteradian(tally);
    if (logScale) {
        // Empty bins sit half a decade below the faintest non-empty one, not at a fixed floor that would
        // stretch the plot.
        float faintest = 0.0f;
        for (float v : values) {
            if (v > 0.0f) faintest = faintest > 0.0f ? std::min(faintest, v) : v;
        }
        const float floor = faintest > 0.0f ? std::log10(faintest) - 0.5f : 0.0f;
        for (float& v : values) v = v > 0.0f ? std::log10(v) : floor;
    }
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    ImGui::PlotLines("##angular", values.data(), static_cast<int>(values.size()), 0,
                     logScale ? "log10 fraction/sr vs angle 0-180 deg" : "fraction/sr vs angle 0-180 deg",
                     values.empty() ? 0.0f : *low, values.empty() ? 1.0f : *high,
                     ImVec2(ImGui::GetContentRegionAvail().x, 60.0f));  // PlotLines takes no -1 "fill" width
    ImGui::End();
}

}  // namespace dropscope::gui
