#include "gui/Actions.hpp"
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
    if (state.job.running()) {
        drawTraceProgress(state, 220.0f);
        ImGui::SameLine();
    }
    if (state.status.error) {
        ImGui::TextColored(kErrorColour, "%s", state.status.text.c_str());
    } else {
        ImGui::TextUnformatted(state.status.text.c_str());
    }
    ImGui::SameLine(display.x - 260.0f);
    ImGui::Text("%zu shapes  %s%s", state.document->shapeCount(), state.placementMode ? "PLACING  " : "",
                state.scenePath.empty() ? "(unsaved scene)" : state.scenePath.filename().c_str());
    ImGui::End();
}

}  // namespace dropscope::gui
