#include "gui/PanelLayout.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace dropscope::gui {

namespace {

// One medium's row: name, n, and its absorption as kappa or sigma (the form the file gave).
void mediumRow(SceneDocument& document, StatusLine& status, MediumId id) {
    Medium medium = document.media()[id];
    ImGui::PushID(static_cast<int>(id));
    bool changed = false;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1.0f);
    changed |= ImGui::InputText("##name", &medium.name, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1.0f);
    changed |= ImGui::InputDouble("##n", &medium.n, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1.0f);
    if (medium.sigma) {
        double sigma = *medium.sigma;
        if (ImGui::InputDouble("sigma##s", &sigma, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
            medium.sigma = sigma;
            changed = true;
        }
    } else {
        double kappa = medium.kappa.value_or(0.0);
        if (ImGui::InputDouble("kappa##k", &kappa, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
            medium.kappa = kappa;
            changed = true;
        }
    }
    if (changed) {
        status.attempt("medium not changed", [&] {
            document.setMedium(id, medium);
            status.say("medium " + medium.name + " changed");
        });
    }
    ImGui::PopID();
}

}  // namespace

void drawMediaPanel(SceneDocument& document, StatusLine& status) {
    placeNextPanel(PanelSide::Left, 0.36f, 0.15f);
    if (!ImGui::Begin("Media")) {
        ImGui::End();
        return;
    }
    const auto& media = document.media();
    ImGui::Text("ambient: %s (Enter applies an edit)", media.at(document.ambient()).name.c_str());
    if (ImGui::BeginTable("media", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("name");
        ImGui::TableSetupColumn("n");
        ImGui::TableSetupColumn("absorption");
        ImGui::TableHeadersRow();
        for (MediumId id = 0; id < media.size(); ++id) mediumRow(document, status, id);
        ImGui::EndTable();
    }
    if (ImGui::Button("Add medium")) {
        Medium medium;
        medium.name = "medium" + std::to_string(media.size());
        medium.n = 1.33;
        status.attempt("no medium added", [&] { document.addMedium(medium); });
    }
    ImGui::End();
}

}  // namespace dropscope::gui
