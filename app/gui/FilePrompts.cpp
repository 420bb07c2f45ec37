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

// The screenshot prompt's own choices: panels or the 3D view alone, the window's size or another.
struct ScreenshotChoice {
    bool panels = false;
    bool windowSize = true;
    int width = 1920;
    int height = 1080;
};

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
    static std::string path;
    static FilePrompt opened = FilePrompt::None;
    static ScreenshotChoice choice;
    if (state.ui.prompt == FilePrompt::None) return;
    const char* title = promptTitle(state.ui.prompt);
    if (opened != state.ui.prompt) {
        path = suggestedName(state, state.ui.prompt);
        opened = state.ui.prompt;
        ImGui::OpenPopup(title);
    }
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        state.ui.prompt = opened = FilePrompt::None;
        return;
    }
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("file", &path, ImGuiInputTextFlags_EnterReturnsTrue);
    if (state.ui.prompt == FilePrompt::Screenshot) screenshotOptions(choice);
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
        state.ui.prompt = opened = FilePrompt::None;
    }
    ImGui::EndPopup();
}

}  // namespace dropscope::gui
