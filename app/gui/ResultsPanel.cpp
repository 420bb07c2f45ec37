#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/PlotWindow.hpp"

#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"

#include <imgui.h>

namespace dropscope::gui {

namespace {

// Escapes per steradian in each angular bin, as a fraction of the photons traced (angular.csv's
// fraction_per_sr, the quantity whose peaks are the rainbows), at the bin's centre.
plot::Figure angularFigure(const AngularTally& angular) {
    plot::Curve curve{"fraction per sr", {}, angular.fractionPerSteradian()};
    for (int bin = 0; bin < angular.bins(); ++bin) {
        curve.x.push_back(0.5 * (angular.lowerEdgeDeg(bin) + angular.lowerEdgeDeg(bin + 1)));
    }
    plot::SubPlot perSteradian{"escaped fraction per sr", {std::move(curve)}, plot::Scale::Log, std::nullopt};
    return {"Angular distribution", "scattering angle (deg)", plot::AxisRange{0.0, 180.0}, {std::move(perSteradian)}};
}

void drawFractions(const TraceResult& result) {
    const FateTally& fates = result.tallies.get<FateTally>();
    const double n = fates.photons() > 0 ? static_cast<double>(fates.photons()) : 1.0;
    ImGui::Text("%llu photons%s, %.2f s", static_cast<unsigned long long>(fates.photons()),
                result.partial ? " (stopped early)" : "", result.seconds);
    ImGui::Text("escaped %.5f  absorbed %.5f", static_cast<double>(fates.escaped()) / n,
                static_cast<double>(fates.absorbed()) / n);
    ImGui::Text("lost %.5f  unscattered %.5f", static_cast<double>(fates.lost()) / n,
                static_cast<double>(fates.unscattered()) / n);
}

}  // namespace

void drawResultsPanel(const TraceState& traces, UiState& ui) {
    plot::PlotWindowState& plotState = ui.panels.angularPlot;
    placeNextPanel(PanelSide::Left, 0.79f, 0.21f);
    if (ImGui::Begin("Results")) {
        if (traces.trace) {
            const TraceResult& result = traces.trace->outcome.result;
            drawFractions(result);
            if (ImGui::Button("Plot...")) plotState.open = true;
            reportItemRect(ui.itemProbe, "results plot");
            ImGui::SameLine();
            ImGui::TextDisabled("angular distribution, %d bins", result.tallies.get<AngularTally>().bins());
        } else {
            ImGui::TextDisabled("no trace yet: fire photons (Space)");
        }
    }
    ImGui::End();
    if (traces.trace) {
        drawPlotWindow(angularFigure(traces.trace->outcome.result.tallies.get<AngularTally>()), plotState, ui.status,
                       ui.itemProbe);
    }
}

}  // namespace dropscope::gui
