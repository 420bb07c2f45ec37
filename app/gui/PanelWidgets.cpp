#include "gui/PanelWidgets.hpp"

#include "gui/TraceActions.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>

namespace dropscope::gui {

bool inputVector3(const char* label, Eigen::Vector3d& v, const char* format, int flags) {
    std::array<double, 3> values{v.x(), v.y(), v.z()};
    if (!ImGui::InputScalarN(label, ImGuiDataType_Double, values.data(), 3, nullptr, nullptr, format, flags)) {
        return false;
    }
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

bool choiceCombo(const char* label, int& chosen, std::span<const char* const> choices, const ItemProbe& probe,
                 const char* help) {
    const int count = static_cast<int>(choices.size());
    chosen = std::clamp(chosen, 0, count - 1);
    bool changed = false;
    const bool open = ImGui::BeginCombo(label, choices[static_cast<std::size_t>(chosen)]);
    reportItemRect(probe, label);
    if (help && !open && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help);
    if (!open) return false;
    for (int k = 0; k < count; ++k) {
        const char* choice = choices[static_cast<std::size_t>(k)];
        if (ImGui::Selectable(choice, k == chosen) && k != chosen) {
            chosen = k;
            changed = true;
        }
        if (probe) reportItemRect(probe, std::string(label) + ": " + choice);
    }
    ImGui::EndCombo();
    return changed;
}

namespace {

ItemRect lastItemRect(std::string text) {
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    return ItemRect{min.x, min.y, max.x, max.y, std::move(text)};
}

}  // namespace

void reportItemRect(const ItemProbe& probe, std::string_view name) {
    if (probe) probe(name, lastItemRect({}));
}

void probedText(const ItemProbe& probe, std::string_view name, const std::string& text, bool wrap) {
    if (wrap) {
        ImGui::TextWrapped("%s", text.c_str());
    } else {
        ImGui::TextUnformatted(text.c_str());
    }
    if (probe) probe(name, lastItemRect(text));
}

bool FieldEdits::track(bool edited, const char* label) {
    if (edited) edited_ = ImGui::GetID(label);
    return edited;
}

void FieldEdits::finish() {
    if (!ImGui::IsAnyItemActive()) editing_ = 0;
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
