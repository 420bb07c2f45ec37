#include "gui/PanelLayout.hpp"
#include "gui/Panels.hpp"
#include "gui/TraceActions.hpp"

#include <imgui.h>

#include <cmath>
#include <string>

namespace dropscope::gui {

namespace {

void photonList(TraceState& traces) {
    const auto& paths = traces.trace->outcome.result.paths;
    ImGui::BeginChild("photons", ImVec2(0.0f, 80.0f), true);
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(paths.size()));
    while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
            const PhotonPath& path = paths[static_cast<std::size_t>(row)];
            const std::string label = "photon " + std::to_string(path.photon) + ": " +
                                      std::string(photonFateName(path.fate)) + ", " +
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

void eventTable(TraceState& traces) {
    const TraceShown& trace = *traces.trace;
    const PhotonPath& path = trace.outcome.result.paths[static_cast<std::size_t>(traces.selectedPath)];
    const auto& media = trace.outcome.scene.media;
    if (ImGui::ArrowButton("previous", ImGuiDir_Left)) stepEvent(traces, -1);
    ImGui::SameLine();
    if (ImGui::ArrowButton("next", ImGuiDir_Right)) stepEvent(traces, +1);
    ImGui::SameLine();
    ImGui::Text("event %d of %zu (Left/Right keys)", traces.selectedEvent + 1, path.events.size());
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("events", 8, flags, ImVec2(0.0f, 150.0f))) return;
    for (const char* header : {"#", "type", "position", "direction", "shape", "n1 -> n2", "R", "weight"}) {
        ImGui::TableSetupColumn(header);
    }
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableHeadersRow();
    for (std::size_t k = 0; k < path.events.size(); ++k) {
        const Event& event = path.events[k];
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
    }
    ImGui::EndTable();
}

}  // namespace

void drawPathPanel(render::LayerOptions& layers, TraceState& traces) {
    placeNextPanel(PanelSide::Right, 0.65f, 0.35f);
    if (!ImGui::Begin("Paths")) {
        ImGui::End();
        return;
    }
    ImGui::Checkbox("paths", &layers.paths);
    ImGui::SameLine();
    ImGui::Checkbox("markers", &layers.markers);
    ImGui::SameLine();
    bool byEvent = layers.pathColouring == render::PathColouring::Event;
    if (ImGui::Checkbox("colour by event", &byEvent)) {
        layers.pathColouring = byEvent ? render::PathColouring::Event : render::PathColouring::Weight;
    }
    if (!traces.trace || traces.trace->outcome.result.paths.empty()) {
        ImGui::TextDisabled("fire photons (Space) with 'paths kept' > 0 to inspect them here");
        ImGui::End();
        return;
    }
    photonList(traces);
    if (traces.selectedPath >= 0) eventTable(traces);
    ImGui::End();
}

}  // namespace dropscope::gui
