#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

#include <string>

namespace dropscope::gui {

namespace {

// Room for the scene's name and shape count at the right.
constexpr float kRightColumnWidth = 260.0f;

// `text` cut to fit `width` pixels, ending in "..." when cut (whole UTF-8 characters kept).
std::string fitted(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
    std::size_t keep = text.size();
    while (keep > 0) {
        --keep;
        while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;  // not mid-character
        const std::string candidate = text.substr(0, keep) + "...";
        if (ImGui::CalcTextSize(candidate.c_str()).x <= width) return candidate;
    }
    return "...";
}

}  // namespace

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
    // A long message (a loss warning) is cut before the right column; hovering shows all of it.
    const float room = display.x - kRightColumnWidth - ImGui::GetCursorPosX() - ImGui::GetStyle().ItemSpacing.x;
    const std::string shown = fitted(status.text(), room);
    if (status.error()) {
        ImGui::TextColored(kErrorColour, "%s", shown.c_str());
    } else {
        ImGui::TextUnformatted(shown.c_str());
    }
    if (shown != status.text() && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
        ImGui::TextUnformatted(status.text().c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    ImGui::SameLine(display.x - kRightColumnWidth);
    const std::filesystem::path& file = state.scene.file();
    ImGui::Text("%zu shapes  %s%s", state.scene.document().shapeCount(), state.placement.active ? "PLACING  " : "",
                file.empty() ? "(unsaved scene)" : file.filename().c_str());
    ImGui::End();
}

}  // namespace dropscope::gui
