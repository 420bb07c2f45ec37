#include "gui/PanelWidgets.hpp"

#include "gui/TraceActions.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <string>

namespace dropscope::gui {

bool inputVector3(const char* label, Eigen::Vector3d& v, const char* format) {
    std::array<double, 3> values{v.x(), v.y(), v.z()};
    if (!ImGui::InputScalarN(label, ImGuiDataType_Double, values.data(), 3, nullptr, nullptr, format)) return false;
    v = Eigen::Vector3d(values[0], values[1], values[2]);
    return true;
}

bool mediumCombo(const char* label, const SceneDocument& document, MediumId& medium) {
    bool changed = false;
    const auto& media = document.media();
    medium = std::min<MediumId>(medium, static_cast<MediumId>(media.size() - 1));
    if (ImGui::BeginCombo(label, media[medium].name.c_str())) {
        for (MediumId m = 0; m < media.size(); ++m) {
            if (ImGui::Selectable(media[m].name.c_str(), m == medium)) {
                medium = m;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

void reportItemRect(const ItemProbe& probe, std::string_view name) {
    if (!probe) return;
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    probe(name, ItemRect{min.x, min.y, max.x, max.y});
}

void drawTraceProgress(AppState& state, float barWidth) {
    const TraceJobProgress progress = state.traces.job.progress();
    const float fraction =
        progress.total > 0 ? static_cast<float>(progress.done) / static_cast<float>(progress.total) : 0.0f;
    const std::string label = progress.buildingOctree
                                  ? std::string("building the octree")
                                  : std::to_string(progress.done) + " / " + std::to_string(progress.total) + " photons";
    ImGui::ProgressBar(fraction, ImVec2(barWidth, 0.0f), label.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel")) cancelTrace(state);
}

}  // namespace dropscope::gui
