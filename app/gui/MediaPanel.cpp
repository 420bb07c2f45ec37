#include "gui/DispersionWindow.hpp"
#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace dropscope::gui {

namespace {

// A number field, or, where a model gives the value, the value at the scene wavelength (the model is
// edited in the Dispersion window).
bool numberCell(const char* label, double& value, bool modelled, const char* format) {
    ImGui::SetNextItemWidth(-1.0f);
    if (!modelled) return ImGui::InputDouble(label, &value, 0.0, 0.0, format, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TextDisabled(format, value);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("at the scene wavelength; its model: Dispersion (last column)");
    return false;
}

// One medium's row: name, n, its absorption as kappa or sigma (the form the file gave), and how they depend
// on the wavelength, a button that opens the Dispersion window on it.
void mediumRow(SceneDocument& document, UiState& ui, MediumId id) {
    StatusLine& status = ui.status;
    Medium medium = document.media()[id];
    ImGui::PushID(static_cast<int>(id));
    bool changed = false;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1.0f);
    changed |= ImGui::InputText("##name", &medium.name, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TableNextColumn();
    changed |= numberCell("##n", medium.n, medium.nModel.has_value(), "%.6g");
    ImGui::TableNextColumn();
    if (medium.sigma) {
        double sigma = *medium.sigma;
        if (numberCell("sigma##s", sigma, medium.sigmaModel.has_value(), "%.4g")) {
            medium.sigma = sigma;
            changed = true;
        }
    } else {
        double kappa = medium.kappa.value_or(0.0);
        if (numberCell("kappa##k", kappa, medium.kappaModel.has_value(), "%.4g")) {
            medium.kappa = kappa;
            changed = true;
        }
    }
    ImGui::TableNextColumn();
    MediaPanelFields& fields = ui.panels.mediaPanel;
    const std::string summary = dispersionSummary(medium) + "##dispersion";
    if (ImGui::SmallButton(summary.c_str())) {
        fields.dispersionOpen = true;
        fields.dispersionOf = id;
    }
    reportItemRect(ui.itemProbe, "dispersion " + medium.name);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s: n and absorption as functions of the wavelength", dispersionSummary(medium).c_str());
    }
    if (changed) {
        status.attempt("medium not changed", [&] {
            document.setMedium(id, medium);
            status.say("medium " + medium.name + " changed");
        });
    }
    ImGui::PopID();
}

void mediaTable(SceneDocument& document, UiState& ui) {
    const auto& media = document.media();
    ImGui::Text("ambient: %s (Enter applies an edit)", media.at(document.ambient()).name.c_str());
    if (ImGui::BeginTable("media", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("name");
        ImGui::TableSetupColumn("n");
        ImGui::TableSetupColumn("absorption");
        ImGui::TableSetupColumn("dispersion");
        ImGui::TableHeadersRow();
        for (MediumId id = 0; id < media.size(); ++id) mediumRow(document, ui, id);
        ImGui::EndTable();
    }
    if (ImGui::Button("Add medium")) {
        Medium medium;
        medium.name = "medium" + std::to_string(media.size());
        medium.n = 1.33;
        ui.status.attempt("no medium added", [&] { document.addMedium(medium); });
    }
}

}  // namespace

void drawMediaPanel(SceneDocument& document, UiState& ui) {
    placeNextPanel(PanelSide::Left, 0.36f, 0.15f);
    if (ImGui::Begin("Media")) mediaTable(document, ui);
    ImGui::End();
    drawDispersionWindow(document, ui.panels.mediaPanel, ui.status, ui.itemProbe);
}

}  // namespace dropscope::gui
