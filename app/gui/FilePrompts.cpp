#include "gui/Actions.hpp"
#include "gui/Panels.hpp"
#include "gui/platform/InputFrame.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace dropscope::gui {

namespace {

const char* promptTitle(FilePrompt prompt) {
    switch (prompt) {
    case FilePrompt::Open: return "Open scene";
    case FilePrompt::SaveAs: return "Save scene as";
    case FilePrompt::ExportPaths: return "Export paths";
    case FilePrompt::Screenshot: return "Screenshot";
    case FilePrompt::None: break;
    }
    return "";
}

std::string suggestedName(const AppState& state, FilePrompt prompt) {
    switch (prompt) {
    case FilePrompt::Open:
    case FilePrompt::SaveAs: return state.scene.file().empty() ? "scene.json" : state.scene.file().string();
    case FilePrompt::ExportPaths: return "paths.jsonl";
    case FilePrompt::Screenshot: return "dropscope.png";
    case FilePrompt::None: break;
    }
    return "";
}

void screenshotOptions(ScreenshotChoice& choice) {
    ImGui::Checkbox("with the panels", &choice.panels);
    if (choice.panels) choice.windowSize = true;  // panels are laid out for the window
    ImGui::BeginDisabled(choice.panels);
    ImGui::Checkbox("the window's size", &choice.windowSize);
    if (!choice.windowSize) {
        ImGui::InputInt("width", &choice.width);
        ImGui::InputInt("height", &choice.height);
    }
    ImGui::EndDisabled();
}

}  // namespace

void drawFilePrompts(AppState& state) {
    if (state.ui.prompt == FilePrompt::None) return;
    FilePromptFields& fields = state.ui.panels.filePrompt;
    std::string& path = fields.path;
    const ScreenshotChoice& choice = fields.screenshot;
    const char* title = promptTitle(state.ui.prompt);
    if (fields.filledFor != state.ui.prompt) {
        path = suggestedName(state, state.ui.prompt);
        fields.filledFor = state.ui.prompt;
        ImGui::OpenPopup(title);
    }
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        state.ui.prompt = fields.filledFor = FilePrompt::None;
        return;
    }
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("file", &path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (state.ui.prompt == FilePrompt::Screenshot) screenshotOptions(fields.screenshot);
    bool done = false;
    if (ImGui::Button("OK") || entered) {
        switch (state.ui.prompt) {
        case FilePrompt::Open: done = openScene(state, path); break;
        case FilePrompt::SaveAs: done = saveScene(state, path); break;
        case FilePrompt::ExportPaths: done = exportPaths(state, path); break;
        case FilePrompt::Screenshot:
            // Two frames later: this dialog has closed and is not in the picture.
            state.ui.screenshot =
                ScreenshotRequest{path, choice.panels, choice.windowSize ? 0 : std::max(choice.width, 1),
                                  choice.windowSize ? 0 : std::max(choice.height, 1), 2};
            done = true;
            break;
        case FilePrompt::None: break;
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(kKeyEscape, false)) done = true;
    if (done) {
        ImGui::CloseCurrentPopup();
        state.ui.prompt = fields.filledFor = FilePrompt::None;
    }
    ImGui::EndPopup();
}

}  // namespace dropscope::gui
