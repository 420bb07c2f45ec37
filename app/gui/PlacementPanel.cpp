#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace dropscope::gui {

namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

}  // namespace

void drawPlacementPanel(PlacementState& placement, SliceSettings& slice, const SceneDocument& document) {
    placeNextPanel(PanelSide::Left, 0.51f, 0.28f);
    if (!ImGui::Begin("Place")) {
        ImGui::End();
        return;
    }
    ImGui::Checkbox("placement mode (P)", &placement.active);
    ImGui::InputDouble("radius", &placement.radius, 0.01, 0.1, "%.4g");
    placement.radius = std::max(placement.radius, 1e-9);
    mediumCombo("medium", document, placement.medium);
    ImGui::Combo("plane normal", &placement.plane.axis, kAxes, 3);
    ImGui::InputDouble("plane at", &placement.plane.offset, 0.1, 1.0, "%.4g");
    ImGui::Separator();
    ImGui::Checkbox("slice plane (L)", &slice.enabled);
    ImGui::Combo("slice normal", &slice.axis, kAxes, 3);
    ImGui::DragScalar("slice at", ImGuiDataType_Double, &slice.offset, 0.01f);
    ImGui::Checkbox("keep the other side", &slice.flip);
    ImGui::End();
}

}  // namespace dropscope::gui
