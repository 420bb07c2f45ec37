#include "gui/Panels.hpp"
#include "gui/Shortcuts.hpp"

#include <imgui.h>

#include <string>

namespace dropscope::gui {

void drawHelpWindow(UiState& ui) {
    if (!ui.showHelp) return;
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                            ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("Help", &ui.showHelp, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return;
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
    ImGui::TextUnformatted("Keyboard (not while typing in a field)");
    if (ImGui::BeginTable("keys", 2, flags)) {
        for (const Shortcut& shortcut : shortcuts()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(shortcut.keys).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(shortcut.action).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::TextUnformatted("Mouse, in the 3D view");
    if (ImGui::BeginTable("mouse", 2, flags)) {
        for (const auto& [gesture, action] : mouseGestures()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(gesture).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::string(action).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace dropscope::gui
