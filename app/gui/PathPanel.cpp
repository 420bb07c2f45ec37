#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/PathFilter.hpp"
#include "gui/PolarisationText.hpp"
#include "gui/SpectralWidgets.hpp"
#include "gui/TraceActions.hpp"
#include "render/Colour.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace dropscope::gui {

namespace {

constexpr std::array<const char*, 4> kColourings{"weight", "event", "DoLP", "wavelength"};  // render::PathColouring
constexpr const char* kColouringHelp =
    "weight: viridis by the weight each segment starts with\n"
    "event: by the type of the event it starts at (the markers' colours)\n"
    "DoLP: viridis by its degree of linear polarisation, 0 purple to 1 yellow;\n"
    "grey when the trace carried no polarisation\n"
    "wavelength: the colour of the photon's wavelength (dim grey outside 360-830 nm)";
constexpr std::array<const char*, 5> kStokesColumns{"I", "Q", "U", "V", "DoLP"};  // stokesCells' order
constexpr int kLegendSteps = 16;  // bands of the viridis legend, enough to read as a ramp
constexpr float kLegendWidth = 120.0f;
constexpr float kColouringWidth = 100.0f;   // the colouring's combo box, on the row of the layer switches
constexpr float kPhotonListHeight = 64.0f;  // three photons
constexpr float kMinTableHeight = 90.0f;    // the header and four events
constexpr float kOrderWidth = 70.0f;        // the filters' combo boxes, with the count of paths kept on their row
constexpr float kHitWidth = 90.0f;

void layerSwitches(render::LayerOptions& layers, const ItemProbe& probe) {
    ImGui::Checkbox("paths", &layers.paths);
    ImGui::SameLine();
    ImGui::Checkbox("markers", &layers.markers);
    ImGui::SameLine();
    int colouring = static_cast<int>(layers.pathColouring);
    ImGui::SetNextItemWidth(kColouringWidth);
    if (choiceCombo("colour", colouring, kColourings, probe, kColouringHelp)) {
        layers.pathColouring = static_cast<render::PathColouring>(colouring);
    }
}

// Viridis from DoLP 0 to 1, and what grey means.
void dolpLegend() {
    ImGui::TextUnformatted("DoLP 0");
    ImGui::SameLine();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float height = ImGui::GetTextLineHeight();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float step = kLegendWidth / kLegendSteps;
    for (int k = 0; k < kLegendSteps; ++k) {
        const render::Colour c = render::viridis((k + 0.5) / kLegendSteps);
        const ImVec2 from(at.x + step * static_cast<float>(k), at.y);
        draw->AddRectFilled(from, ImVec2(from.x + step, at.y + height),
                            ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1.0f)));
    }
    ImGui::Dummy(ImVec2(kLegendWidth, height));
    ImGui::SameLine();
    ImGui::TextUnformatted("1, grey: none");
}

// "532 nm", "420.405 nm": a photon's wavelength, to six digits (as its other numbers are shown).
std::string wavelengthText(double wavelengthNm) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g nm", wavelengthNm);
    return text;
}

// The colours of the visible wavelengths, 380 to 780 nm.
void wavelengthLegend() {
    ImGui::TextUnformatted("380 nm");
    ImGui::SameLine();
    wavelengthBar(kVisibleRangeNm[0], kVisibleRangeNm[1], kLegendWidth, ImGui::GetTextLineHeight());
    ImGui::SameLine();
    ImGui::TextUnformatted("780 nm");
}

// The filters by ray order and by detector hit (PathFilter.hpp), on one row; the number of paths they keep.
void pathFilters(TraceState& traces, std::size_t kept, const ItemProbe& probe) {
    const std::vector<Detector>& detectors = traces.trace->outcome.scene.detectors;
    PathFilter& filter = traces.pathFilter;
    ImGui::SetNextItemWidth(kOrderWidth);
    choiceCombo("order", filter.order, kOrderChoices, probe,
                "the ray order: p = interface events at the one shape met - 1 (p2: the primary bow);\n"
                "multiple: met two shapes or more; unscattered: met none");
    if (!detectors.empty()) {
        ImGui::SameLine();
        std::vector<std::string> names{"any"};
        std::vector<std::size_t> indices{detectors.size()};
        for (std::size_t d = 0; d < detectors.size(); ++d) {
            if (detectors[d].type == DetectorType::ShapeAbsorption) continue;
            names.push_back(detectors[d].name);
            indices.push_back(d);
        }
        std::vector<const char*> choices;
        for (const std::string& name : names) choices.push_back(name.c_str());
        int chosen = 0;
        for (std::size_t c = 1; c < indices.size(); ++c) {
            if (filter.detector == indices[c]) chosen = static_cast<int>(c);
        }
        ImGui::SetNextItemWidth(kHitWidth);
        if (choiceCombo("hit", chosen, choices, probe,
                        "paths that crossed this plane detector or ended on it,\nor escaped into this far-field "
                        "camera's view")) {
            filter.detector = chosen > 0 ? std::optional(indices[static_cast<std::size_t>(chosen)]) : std::nullopt;
        }
    }
    ImGui::SameLine();
    probedText(probe, "paths kept",
               std::to_string(kept) + " of " + std::to_string(traces.trace->outcome.result.paths.size()));
}

void photonList(TraceState& traces, const std::vector<int>& kept) {
    const auto& paths = traces.trace->outcome.result.paths;
    ImGui::BeginChild("photons", ImVec2(0.0f, kPhotonListHeight), true);
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(kept.size()));
    while (clipper.Step()) {
        for (int shown = clipper.DisplayStart; shown < clipper.DisplayEnd; ++shown) {
            const int row = kept[static_cast<std::size_t>(shown)];
            const PhotonPath& path = paths[static_cast<std::size_t>(row)];
            const std::string label = "photon " + std::to_string(path.photon) + ": " +
                                      wavelengthText(path.wavelengthNm) + ", " +
                                      std::string(photonFateName(path.fate)) + ", " + orderName(rayOrder(path)) + ", " +
                                      std::to_string(path.events.size()) + " events";
            if (ImGui::Selectable(label.c_str(), row == traces.selectedPath)) selectEvent(traces, row, 0);
        }
    }
    ImGui::EndChild();
}

std::string shapeText(const TraceShown& trace, ShapeId shape) {
    if (shape == RayHit::kNone) return "-";
    const auto& slots = trace.slotOfShape;
    return std::to_string(shape < slots.size() ? slots[shape] : shape);
}

// The current event's polarisation in words: what the ellipse drawn there shows.
void eventPolarisation(const Event& event, const ItemProbe& probe) {
    probedText(probe, "event polarisation", polarisationSummary(event.polarisation), true);
    if (event.polarisation && ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s", referenceText(*event.polarisation).c_str());
    }
}

// Its I, Q, U, V and DoLP, one cell each, the frame in their tooltip.
void stokesColumns(const Event& event, std::size_t row, const ItemProbe& probe) {
    const std::array<std::string, 5> cells = stokesCells(event.polarisation);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        ImGui::TableNextColumn();
        if (probe) {
            probedText(probe, "event " + std::to_string(row) + " " + kStokesColumns[c], cells[c]);
        } else {
            ImGui::TextUnformatted(cells[c].c_str());
        }
        if (event.polarisation && ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s", referenceText(*event.polarisation).c_str());
        }
    }
}

void eventRow(TraceState& traces, const TraceShown& trace, const Event& event, std::size_t k, const ItemProbe& probe) {
    const auto& media = trace.outcome.scene.media;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string index = std::to_string(k);
    if (ImGui::Selectable(index.c_str(), static_cast<int>(k) == traces.selectedEvent,
                          ImGuiSelectableFlags_SpanAllColumns)) {
        selectEvent(traces, traces.selectedPath, static_cast<int>(k));
    }
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(std::string(eventTypeName(event.type)).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.4g %.4g %.4g", event.position.x(), event.position.y(), event.position.z());
    ImGui::TableNextColumn();
    ImGui::Text("%.3f %.3f %.3f", event.direction.x(), event.direction.y(), event.direction.z());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(shapeText(trace, event.shape).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.4g -> %.4g", media.at(event.from).n, media.at(event.to).n);
    ImGui::TableNextColumn();
    if (std::isnan(event.reflectance)) {
        ImGui::TextUnformatted("-");
    } else {
        ImGui::Text("%.4f", event.reflectance);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.4g", event.weight);
    stokesColumns(event, k, probe);
}

void eventTable(TraceState& traces, const ItemProbe& probe) {
    const TraceShown& trace = *traces.trace;
    const PhotonPath& path = trace.outcome.result.paths[static_cast<std::size_t>(traces.selectedPath)];
    if (ImGui::ArrowButton("previous", ImGuiDir_Left)) stepEvent(traces, -1);
    ImGui::SameLine();
    if (ImGui::ArrowButton("next", ImGuiDir_Right)) stepEvent(traces, +1);
    ImGui::SameLine();
    ImGui::Text("event %d of %zu (Left/Right keys)", traces.selectedEvent + 1, path.events.size());
    probedText(probe, "photon wavelength", wavelengthText(path.wavelengthNm) + ";");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the photon's vacuum wavelength: n1 and n2 are at it");
    if (path.events.empty()) return;
    ImGui::SameLine();
    eventPolarisation(path.events[static_cast<std::size_t>(traces.selectedEvent)], probe);
    // Columns can be dragged into another order, or hidden from the header's context menu.
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit |
                                  ImGuiTableFlags_Reorderable | ImGuiTableFlags_Hideable;
    const float height = std::max(kMinTableHeight, ImGui::GetContentRegionAvail().y);
    if (!ImGui::BeginTable("events", 8 + static_cast<int>(kStokesColumns.size()), flags, ImVec2(0.0f, height))) {
        return;
    }
    for (const char* header : {"#", "type", "position", "direction", "shape", "n1 -> n2", "R", "weight"}) {
        ImGui::TableSetupColumn(header);
    }
    for (const char* header : kStokesColumns) ImGui::TableSetupColumn(header);
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableHeadersRow();
    // Only the rows in view are drawn: a photon trapped until the event cap has 10,000 events.
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(path.events.size()));
    while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
            const auto k = static_cast<std::size_t>(row);
            eventRow(traces, trace, path.events[k], k, probe);
        }
    }
    ImGui::EndTable();
}

}  // namespace

void drawPathPanel(render::LayerOptions& layers, TraceState& traces, const ItemProbe& probe) {
    placeNextPanel(PanelSide::Right, 0.59f, 0.41f);  // under the Octree panel, collapsed at first
    if (!ImGui::Begin("Paths")) {
        ImGui::End();
        return;
    }
    layerSwitches(layers, probe);
    if (layers.pathColouring == render::PathColouring::Dolp) dolpLegend();
    if (layers.pathColouring == render::PathColouring::Wavelength) wavelengthLegend();
    if (!traces.trace || traces.trace->outcome.result.paths.empty()) {
        ImGui::TextDisabled("fire photons (Space) with 'paths kept' > 0 to inspect them here");
        ImGui::End();
        return;
    }
    const std::vector<int> kept =
        filterPaths(traces.trace->outcome.result.paths, traces.trace->outcome.scene.detectors, traces.pathFilter);
    pathFilters(traces, kept.size(), probe);
    photonList(traces, kept);
    if (traces.selectedPath >= 0) eventTable(traces, probe);
    ImGui::End();
}

}  // namespace dropscope::gui
