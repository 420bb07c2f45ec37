#include "gui/EnergyBudget.hpp"
#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/PathFilter.hpp"
#include "gui/PlotWindow.hpp"
#include "gui/TraceActions.hpp"

#include "spectrum/Colour.hpp"
#include "tally/AngularTally.hpp"
#include "tally/DetectorTallies.hpp"
#include "tally/FateTally.hpp"
#include "tally/OrderTally.hpp"
#include "tally/SpectralAngularTally.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <variant>
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
// The traced photons' share in each angular bin that was scattered: angular.csv's fraction less the unscattered
// photons, which escape along the axis into the first bin.
std::vector<double> scatteredShares(const TallySet& tallies) {
    std::vector<double> shares = tallies.get<AngularTally>().columns().fraction;
    const FateTally& fates = tallies.get<FateTally>();
    if (!shares.empty() && fates.photons() > 0) {
        shares[0] -= static_cast<double>(fates.unscattered()) / static_cast<double>(fates.photons());
    }
    return shares;
}

// Mie theory's curves for the angular plot in the traced curve's units: its phase function times the traced
// share that was scattered (so the two match where ray optics is right), and -P12/P11 (unpolarised light).
void addMieCurves(plot::Figure& figure, const TallySet& tallies, const MieResult& mie,
                  const std::vector<double>& centres, bool polarisation) {
    const std::vector<double> traced = scatteredShares(tallies);
    double scattered = 0.0;
    for (double share : traced) scattered += share;
    const std::vector<double>& fraction = mie.bins.fraction;
    if (fraction.size() != centres.size() || !(mie.efficiencies.qsca > 0.0)) return;
    std::vector<double> perSteradian;
    std::vector<double> ratio;
    for (std::size_t bin = 0; bin < fraction.size(); ++bin) {
        perSteradian.push_back(fraction[bin] / mie.efficiencies.qsca * scattered /
                               angularBinSolidAngle(static_cast<int>(bin), static_cast<int>(fraction.size())));
        ratio.push_back(fraction[bin] > 0.0 ? -mie.bins.s12[bin] / fraction[bin] : std::nan(""));
    }
    const std::array<float, 3> mieColour{0.95f, 0.35f, 0.35f};
    figure.subPlots[0].curves.push_back({"Mie theory", centres, std::move(perSteradian), mieColour});
    if (polarisation) figure.subPlots.back().curves.push_back({"Mie -P12/P11", centres, std::move(ratio), mieColour});
}

plot::Figure angularFigure(const TallySet& tallies, bool unpolarisedSources, const MieResult* mie) {
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
    if (!angular.stokes()) {
        if (mie) addMieCurves(figure, tallies, *mie, centres, false);
        return figure;
    }
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
    if (mie) addMieCurves(figure, tallies, *mie, centres, unpolarisedSources);
    return figure;
}

// Bands of the scattering angle where ray optics and Mie theory are compared (docs/validation.md, "Ray optics with
// diffraction against Mie theory"), in degrees.
constexpr std::array<std::array<double, 2>, 8> kMieBands{
    {{0, 1}, {1, 5}, {5, 15}, {15, 60}, {60, 130}, {130, 139}, {139, 150}, {150, 180}}};

// The traced light against Mie theory: one line (x, Q_sca, g of both) and, folded, the ratio of the traced
// phase function to Mie's in each band. Both are normalised to their scattered light, so the comparison holds
// for any beam; a cloud's multiple scattering is in the traced light and not in Mie's.
void drawMieComparison(const TraceOutcome& outcome, const ItemProbe& probe) {
    if (!outcome.mie || !outcome.mieSpheres) {
        if (!outcome.mieNote.empty()) {
            probedText(probe, "mie summary", "Mie theory: none (" + outcome.mieNote + ")", true);
        }
        return;
    }
    const MieResult& mie = *outcome.mie;
    const std::vector<double> traced = scatteredShares(outcome.result.tallies);
    const std::size_t bins = traced.size();
    if (mie.bins.fraction.size() != bins) return;
    double tracedTotal = 0.0;
    double tracedCos = 0.0;
    for (std::size_t bin = 0; bin < bins; ++bin) {
        tracedTotal += traced[bin];
        tracedCos +=
            traced[bin] * std::cos(std::numbers::pi * (static_cast<double>(bin) + 0.5) / static_cast<double>(bins));
    }
    const SphereSceneMie& spheres = *outcome.mieSpheres;
    char text[160];
    std::snprintf(text, sizeof text, "Mie: %s, x %.4g, m %.4g%+.2gi",
                  spheres.spheres == 1 ? "one sphere" : (std::to_string(spheres.spheres) + " spheres").c_str(),
                  mie.xMean, spheres.m.real(), spheres.m.imag());
    probedText(probe, "mie summary", text);
    std::snprintf(text, sizeof text, "  Q_sca %.4f, g %.4f (traced %.4f)", mie.efficiencies.qsca, mie.efficiencies.g,
                  tracedTotal > 0.0 ? tracedCos / tracedTotal : std::nan(""));
    probedText(probe, "mie efficiencies", text);
    const bool unfolded = ImGui::TreeNode("traced / Mie by band");
    reportItemRect(probe, "mie bands");
    if (!unfolded) return;
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg;
    if (ImGui::BeginTable("mie bands", 4, flags)) {
        for (const char* header : {"band (deg)", "traced", "Mie", "traced / Mie"}) ImGui::TableSetupColumn(header);
        ImGui::TableHeadersRow();
        for (const auto& band : kMieBands) {
            double tracedShare = 0.0;
            double mieShare = 0.0;
            for (std::size_t bin = 0; bin < bins; ++bin) {
                const double centre = 180.0 * (static_cast<double>(bin) + 0.5) / static_cast<double>(bins);
                if (centre < band[0] || centre >= band[1]) continue;
                tracedShare += traced[bin];
                mieShare += mie.bins.fraction[bin];
            }
            tracedShare /= tracedTotal;
            mieShare /= mie.efficiencies.qsca;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%g-%g", band[0], band[1]);
            ImGui::TableNextColumn();
            ImGui::Text("%.5f", tracedShare);
            ImGui::TableNextColumn();
            ImGui::Text("%.5f", mieShare);
            ImGui::TableNextColumn();
            char ratio[32];
            std::snprintf(ratio, sizeof ratio, "%.3f", tracedShare / mieShare);
            char name[48];
            std::snprintf(name, sizeof name, "mie ratio %g-%g", band[0], band[1]);
            probedText(probe, name, ratio);
        }
        ImGui::EndTable();
    }
    ImGui::TreePop();
}

// Escapes per steradian of each ray order (OrderTally) as a fraction of the photons traced, at the angular
// bins' centres: p0 .. p4, p5+ and multiple, log scale (NaN, not drawn, where none escaped).
plot::Figure ordersFigure(const OrderTally& orders) {
    const int bins = orders.bins();
    const double photons = std::max<double>(static_cast<double>(orders.photons()), 1.0);
    std::vector<double> centres;
    for (int bin = 0; bin < bins; ++bin) centres.push_back(90.0 * (bin + bin + 1) / bins);
    const auto perSteradian = [&](const std::vector<std::uint64_t>& counts) {
        std::vector<double> y;
        for (std::size_t b = 0; b < counts.size(); ++b) {
            y.push_back(counts[b] > 0
                            ? static_cast<double>(counts[b]) / photons / angularBinSolidAngle(static_cast<int>(b), bins)
                            : std::nan(""));
        }
        return y;
    };
    plot::SubPlot subPlot{"escaped fraction per sr, by ray order", {}, plot::Scale::Log, {}};
    for (std::size_t p = 0; p < OrderTally::kOrderColumns; ++p) {
        subPlot.curves.push_back({orderName(static_cast<int>(p)), centres, perSteradian(orders.order(p))});
    }
    subPlot.curves.push_back({"multiple", centres, perSteradian(orders.multiple())});
    if (orders.withDiffraction()) subPlot.curves.push_back({"diffraction", centres, perSteradian(orders.diffracted())});
    return {"Ray orders", "scattering angle (deg)", plot::AxisRange{0.0, 180.0}, {std::move(subPlot)}};
}

// Single and multiple scattering shares, the orders' plot button.
void drawOrders(const OrderTally& orders, ResultViews& views, const ItemProbe& probe) {
    const double n = std::max<double>(static_cast<double>(orders.photons()), 1.0);
    char text[96];
    std::snprintf(text, sizeof text, "single %.5f  multiple %.5f", static_cast<double>(orders.singleTotal()) / n,
                  static_cast<double>(orders.multipleTotal()) / n);
    probedText(probe, "orders shares", text);
    ImGui::SameLine();
    if (ImGui::SmallButton("Orders...")) views.ordersPlot.open = true;
    reportItemRect(probe, "orders plot");
}

// The shape-absorption detector's table: each shape that absorbed light, its medium and share.
void absorptionTable(const ShapeAbsorptionTally& tally) {
    ResultReport report;
    tally.report(report);
    const ResultTable* table = report.table(tally.name());
    if (!table || table->rows() == 0) return ImGui::TextDisabled("  nothing absorbed in a shape");
    const auto& shapes = std::get<std::vector<std::uint64_t>>(table->columns[0].values);
    const auto& names = std::get<std::vector<std::string>>(table->columns[1].values);
    const auto& media = std::get<std::vector<std::string>>(table->columns[2].values);
    const auto& fractions = std::get<std::vector<double>>(table->columns[3].values);
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY;
    const float height = std::min(6.0f, static_cast<float>(table->rows() + 1)) * ImGui::GetTextLineHeightWithSpacing();
    if (!ImGui::BeginTable(tally.name().data(), 4, flags, ImVec2(0.0f, height))) return;
    for (const char* header : {"shape", "name", "medium", "fraction"}) ImGui::TableSetupColumn(header);
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableHeadersRow();
    for (std::size_t row = 0; row < table->rows(); ++row) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(shapes[row]));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(names[row].c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(media[row].c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%.5f", fractions[row]);
    }
    ImGui::EndTable();
}

// The plane and far-field detectors' image buttons on one line (their windows: DetectorWindows.cpp), each
// detector's share of the photons in its tooltip; below, each shape-absorption detector's table, folded.
void drawDetectors(const TallySet& tallies, ResultViews& views, const ItemProbe& probe) {
    const std::vector<const DetectorTally*> detectors = tallies.all<DetectorTally>();
    const bool images = std::any_of(detectors.begin(), detectors.end(), [](const DetectorTally* tally) {
        return tally->detector().type != DetectorType::ShapeAbsorption;
    });
    if (images) ImGui::TextUnformatted("images:");
    for (const DetectorTally* tally : detectors) {
        const Detector& detector = tally->detector();
        if (detector.type == DetectorType::ShapeAbsorption) continue;
        ImGui::SameLine();
        if (ImGui::SmallButton(detector.name.c_str())) {
            DetectorView& view = views.detectors[detector.name];
            view.open = true;
            view.focus = true;
        }
        reportItemRect(probe, "detector " + detector.name);
        if (ImGui::IsItemHovered()) {
            const double n = std::max<double>(static_cast<double>(tally->photons()), 1.0);
            ImGui::SetTooltip("%s %s: %llu hits (%.5f of the photons); its image in a window",
                              std::string(detectorTypeName(detector.type)).c_str(), detector.name.c_str(),
                              static_cast<unsigned long long>(tally->hits()), static_cast<double>(tally->hits()) / n);
        }
    }
    for (const DetectorTally* tally : detectors) {
        const auto* absorption = dynamic_cast<const ShapeAbsorptionTally*>(tally);
        if (!absorption) continue;
        const std::string title = "absorbed by shape (" + tally->detector().name + ")";
        if (ImGui::TreeNode(title.c_str())) {
            absorptionTable(*absorption);
            ImGui::TreePop();
        }
    }
}

// The budget's bar and window button, the orders, the detectors: from the tallies so far while a run goes on.
void drawDetectorResults(const ShownTallies& shown, ResultViews& views, const ItemProbe& probe) {
    if (shown.filling) {
        ImGui::Text("filling in: %llu of %llu photons", static_cast<unsigned long long>(shown.photons),
                    static_cast<unsigned long long>(shown.requested));
    }
    if (const auto* budget = shown.tallies->find<BudgetTally>()) {
        ImGui::TextUnformatted("budget");
        ImGui::SameLine();
        drawBudgetBar(*budget, std::max(ImGui::GetContentRegionAvail().x - 70.0f, 40.0f), probe);
        ImGui::SameLine();
        if (ImGui::SmallButton("Budget...")) views.budgetOpen = true;
        reportItemRect(probe, "budget window");
    }
    if (const auto* orders = shown.tallies->find<OrderTally>()) drawOrders(*orders, views, probe);
    drawDetectors(*shown.tallies, views, probe);
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

void drawResultsPanel(TraceState& traces, UiState& ui) {
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
            drawMieComparison(traces.trace->outcome, ui.itemProbe);
        } else if (!traces.partial) {
            ImGui::TextDisabled("no trace yet: fire photons (Space)");
        }
        const ShownTallies shown = shownTallies(traces);
        if (shown.tallies) drawDetectorResults(shown, traces.views, ui.itemProbe);
    }
    ImGui::End();
    const ShownTallies shown = shownTallies(traces);
    const auto* budget = shown.tallies ? shown.tallies->find<BudgetTally>() : nullptr;
    if (budget && traces.views.budgetOpen) drawBudgetWindow(*budget, traces.views.budgetOpen, ui.itemProbe);
    const auto* orders = shown.tallies ? shown.tallies->find<OrderTally>() : nullptr;
    if (orders && traces.views.ordersPlot.open) {
        drawPlotWindow(ordersFigure(*orders), traces.views.ordersPlot, ui.status, ui.itemProbe);
    }
    if (traces.trace && plotState.open) {
        const std::vector<Source>& sources = traces.trace->outcome.scene.sources;
        const bool unpolarised = std::all_of(sources.begin(), sources.end(), [](const Source& source) {
            return source.polarisation.kind == PolarisationKind::Unpolarised;
        });
        const TraceOutcome& outcome = traces.trace->outcome;
        drawPlotWindow(angularFigure(outcome.result.tallies, unpolarised, outcome.mie ? &*outcome.mie : nullptr),
                       plotState, ui.status, ui.itemProbe);
    }
}

}  // namespace dropscope::gui
