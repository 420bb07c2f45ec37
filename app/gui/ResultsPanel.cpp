#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/PlotWindow.hpp"

#include "spectrum/Colour.hpp"
#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"
#include "tally/SpectralAngularTally.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace dropscope::gui {

namespace {

// "450-500 nm": a band's name in the legend and the CSV.
std::string bandName(double loNm, double hiNm) {
    char text[48];
    std::snprintf(text, sizeof text, "%.4g-%.4g nm", loNm, hiNm);
    return text;
}

// Escapes per steradian in each wavelength band as a share of all the photons traced (the bands add up to
// the angular distribution), one curve per band in the colour of its centre's wavelength.
plot::SubPlot bandsSubPlot(const SpectralAngularTally& spectral, const std::vector<double>& centres) {
    const WavelengthBins& bins = spectral.wavelengths();
    plot::SubPlot subPlot{"fraction per sr, by wavelength", {}, plot::Scale::Log, {}};
    for (int k = 0; k < bins.count; ++k) {
        const double lo = bins.edgeNm(k);
        const double hi = bins.edgeNm(k + 1);
        const Rgb colour = displayColourOfWavelength(0.5 * (lo + hi));
        subPlot.curves.push_back(
            {bandName(lo, hi), centres, spectral.bands()[static_cast<std::size_t>(k)].columns().perSteradian,
             std::array{static_cast<float>(colour[0]), static_cast<float>(colour[1]), static_cast<float>(colour[2])}});
    }
    return subPlot;
}

// Escapes per steradian in each angular bin, as a fraction of the photons traced (angular.csv's
// fraction_per_sr, the quantity whose peaks are the rainbows), at the bin's centre; with wavelength bands,
// below it the same per band (bandsSubPlot); with polarisation, below those the degree of linear
// polarisation and -Q/I in the scattering-plane frame (> 0 polarised across the plane; named -P12/P11 when
// every source is unpolarised, which it then is) (NaN, not drawn, in empty bins).
plot::Figure angularFigure(const TallySet& tallies, bool unpolarisedSources) {
    const AngularTally& angular = tallies.get<AngularTally>();
    const AngularTally::Columns columns = angular.columns();
    std::vector<double> centres;
    for (int bin = 0; bin < angular.bins(); ++bin) {
        centres.push_back(0.5 * (angular.lowerEdgeDeg(bin) + angular.lowerEdgeDeg(bin + 1)));
    }
    plot::Figure figure{"Angular distribution", "scattering angle (deg)", plot::AxisRange{0.0, 180.0}, {}};
    figure.subPlots.push_back(
        {"escaped fraction per sr", {{"fraction per sr", centres, columns.perSteradian}}, plot::Scale::Log, {}});
    const auto* spectral = tallies.find<SpectralAngularTally>();
    if (spectral && spectral->wavelengths().count > 1) figure.subPlots.push_back(bandsSubPlot(*spectral, centres));
    if (!angular.stokes()) return figure;
    std::vector<double> ratio;
    std::vector<double> dolp;
    for (std::size_t bin = 0; bin < centres.size(); ++bin) {
        const bool empty = !(columns.fraction[bin] > 0.0);
        ratio.push_back(empty ? std::nan("") : -columns.stokesQ[bin] / columns.fraction[bin]);
        dolp.push_back(empty ? std::nan("") : columns.dolp[bin]);
    }
    // DoLP first, so -Q/I is drawn over it: in the scattering-plane frame U averages out, and where
    // -Q/I > 0 the two coincide (DoLP = |Q|/I); drawn last, DoLP hid -Q/I there.
    figure.subPlots.push_back(
        {"polarisation",
         {{"DoLP", centres, std::move(dolp)}, {unpolarisedSources ? "-P12/P11" : "-Q/I", centres, std::move(ratio)}},
         plot::Scale::Linear,
         plot::AxisRange{-1.0, 1.0}});
    return figure;
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
            const auto* spectral = result.tallies.find<SpectralAngularTally>();
            if (spectral && spectral->wavelengths().count > 1) {
                ImGui::TextDisabled("angular distribution, %d bins, %d wavelength bands",
                                    result.tallies.get<AngularTally>().bins(), spectral->wavelengths().count);
            } else {
                ImGui::TextDisabled("angular distribution, %d bins", result.tallies.get<AngularTally>().bins());
            }
        } else {
            ImGui::TextDisabled("no trace yet: fire photons (Space)");
        }
    }
    ImGui::End();
    if (traces.trace && plotState.open) {
        const std::vector<Source>& sources = traces.trace->outcome.scene.sources;
        const bool unpolarised = std::all_of(sources.begin(), sources.end(), [](const Source& source) {
            return source.polarisation.kind == PolarisationKind::Unpolarised;
        });
        drawPlotWindow(angularFigure(traces.trace->outcome.result.tallies, unpolarised), plotState, ui.status,
                       ui.itemProbe);
    }
}

}  // namespace dropscope::gui
