#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace dropscope::gui {

namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

}  // namespace

void drawPlacementPanel(AppState& state) {
    placeNextPanel(PanelSide::Left, 0.51f, 0.28f);
    if (!ImGui::Begin("Place")) {
        ImGui::End();
        return;
    }
    ImGui::Checkbox("placement mode (P)", &state.placementMode);
    ImGui::InputDouble("radius", &state.placementRadius, 0.01, 0.1, "%.4g");
    state.placementRadius = std::max(state.placementRadius, 1e-9);
    mediumCombo("medium", *state.document, state.placementMedium);
    ImGui::Combo("plane normal", &state.placementPlane.axis, kAxes, 3);
    ImGui::InputDouble("plane at", &state.placementPlane.offset, 0.1, 1.0, "%.4g");
    ImGui::Separator();
    ImGui::Checkbox("slice plane (L)", &state.slice.enabled);
    ImGui::Combo("slice normal", &state.slice.axis, kAxes, 3);
    ImGui::DragScalar("slice at", ImGuiDataType_Double, &state.slice.offset, 0.01f);
    ImGui::Checkbox("keep the other side", &state.slice.flip);
    ImGui::End();
}

}  // namespace dropscope::gui
