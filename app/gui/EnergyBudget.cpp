#include "gui/EnergyBudget.hpp"

#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"

#include <imgui.h>

#include <array>
#include <cstdio>
#include <string>
#include <variant>

namespace dropscope::gui {

namespace {

// The four ends of a photon, in the budget's order, and their colours in the stacked bar.
constexpr std::array<const char*, 4> kEnds{"escaped", "absorbed", "detected", "lost"};
constexpr std::array<ImU32, 4> kEndColours{IM_COL32(90, 160, 230, 255), IM_COL32(230, 150, 60, 255),
                                           IM_COL32(120, 200, 110, 255), IM_COL32(200, 80, 80, 255)};

// A row's words: "escaped", or under it "into sky" (far field), "elsewhere", "in water" (medium), "on screen"
// (absorbing detector), "event_cap" (reason).
std::string rowName(const std::vector<std::string>& path) {
    if (path.size() <= 3) return path[1];
    const std::string& group = path[2];
    const std::string& name = path.size() > 4 ? path[3] : group;
    if (group == "far_field") return "  into " + name;
    if (group == "by_medium") return "  in " + name;
    if (group == "by_detector") return "  on " + name;
    return "  " + name;
}

double shareAt(const ResultReport& report, std::vector<std::string> path) {
    path.back() = "share";
    const SummaryValue* value = report.find(path);
    return value && std::holds_alternative<double>(*value) ? std::get<double>(*value) : 0.0;
}

}  // namespace

void drawBudgetBar(const BudgetTally& budget, float width, const ItemProbe& probe) {
    ResultReport report;
    budget.report(report);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float height = ImGui::GetTextLineHeight();
    ImGui::Dummy(ImVec2(width, height));
    reportItemRect(probe, "budget bar");
    ImDrawList* draw = ImGui::GetWindowDrawList();
    float x = at.x;
    std::string tooltip;
    for (std::size_t end = 0; end < kEnds.size(); ++end) {
        const double share = shareAt(report, {"budget", kEnds[end], "count"});
        const float w = width * static_cast<float>(share);
        draw->AddRectFilled(ImVec2(x, at.y), ImVec2(x + w, at.y + height), kEndColours[end]);
        x += w;
        char line[64];
        std::snprintf(line, sizeof line, "%s%s %.4f", end > 0 ? "\n" : "", kEnds[end], share);
        tooltip += line;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip.c_str());
}

void drawBudgetWindow(const BudgetTally& budget, bool& open, const ItemProbe& probe) {
    // At the top left of the 3D view, beside the panel column.
    ImGui::SetNextWindowPos(ImVec2(kPanelWidth + 10.0f, kMenuHeight + 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380.0f, 330.0f), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Energy budget", &open)) return ImGui::End();
    ResultReport report;
    budget.report(report);
    ImGui::Text("%llu photons: every one escaped, absorbed, detected or lost",
                static_cast<unsigned long long>(budget.photons()));
    drawBudgetBar(budget, ImGui::GetContentRegionAvail().x, probe);
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("budget", 3, flags)) {
        ImGui::TableSetupColumn("where");
        ImGui::TableSetupColumn("photons");
        ImGui::TableSetupColumn("share");
        ImGui::TableHeadersRow();
        for (const SummaryEntry& entry : report.summary()) {
            if (entry.path.size() < 3 || entry.path.back() != "count") continue;
            const bool total = entry.path.size() == 3;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            if (total) {
                ImGui::TextUnformatted(rowName(entry.path).c_str());
            } else {
                ImGui::TextDisabled("%s", rowName(entry.path).c_str());
            }
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(std::get<std::uint64_t>(entry.value)));
            ImGui::TableNextColumn();
            ImGui::Text("%.5f", shareAt(report, entry.path));
            if (total) reportItemRect(probe, "budget " + entry.path[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace dropscope::gui
