#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

namespace dropscope::gui {

void drawStatusBar(AppState& state) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.0f, display.y - kStatusHeight));
    ImGui::SetNextWindowSize(ImVec2(display.x, kStatusHeight));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::Begin("##status", nullptr, flags);
    if (state.traces.job.running()) {
        drawTraceProgress(state, 220.0f);
        ImGui::SameLine();
    }
    const StatusLine& status = state.ui.status;
    if (status.error()) {
        ImGui::TextColored(kErrorColour, "%s", status.text().c_str());
    } else {
        ImGui::TextUnformatted(status.text().c_str());
    }
    ImGui::SameLine(display.x - 260.0f);
    const std::filesystem::path& file = state.scene.file();
    ImGui::Text("%zu shapes  %s%s", state.scene.document().shapeCount(), state.placement.active ? "PLACING  " : "",
                file.empty() ? "(unsaved scene)" : file.filename().c_str());
    ImGui::End();
}

}  // namespace dropscope::gui
