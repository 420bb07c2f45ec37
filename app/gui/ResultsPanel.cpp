#include "gui/PanelLayout.hpp"
#include "gui/Panels.hpp"

#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dropscope::gui {

namespace {

// Escapes per steradian in each angular bin, as a fraction of the photons traced: angular.csv's
// fraction_per_sr, the quantity whose peaks are the rainbows.
std::vector<float> perSteradian(const AngularTally& angular) {
    std::vector<float> values(static_cast<std::size_t>(angular.bins()), 0.0f);
    if (angular.photons() == 0) return values;
    const std::vector<double> perSr = angular.columns().perSteradian;
    std::transform(perSr.begin(), perSr.end(), values.begin(), [](double v) { return static_cast<float>(v); });
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
    const FateTally& fates = result.tallies.get<FateTally>();
    const double n = fates.photons() > 0 ? static_cast<double>(fates.photons()) : 1.0;
    ImGui::Text("%llu photons%s, %.2f s", static_cast<unsigned long long>(fates.photons()),
                result.partial ? " (stopped early)" : "", result.seconds);
    ImGui::Text("escaped %.5f  absorbed %.5f", static_cast<double>(fates.escaped()) / n,
                static_cast<double>(fates.absorbed()) / n);
    ImGui::Text("lost %.5f  unscattered %.5f", static_cast<double>(fates.lost()) / n,
                static_cast<double>(fates.unscattered()) / n);
    ImGui::Checkbox("log scale", &logScale);
    std::vector<float> values = perSteradian(result.tallies.get<AngularTally>());
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
