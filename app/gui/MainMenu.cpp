#include "gui/Actions.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

namespace dropscope::gui {

void drawMainMenu(AppState& state) {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open scene...", "Ctrl+O")) state.prompt = FilePrompt::Open;
        if (ImGui::MenuItem("Save scene", "Ctrl+S", false, !state.scenePath.empty())) saveScene(state, state.scenePath);
        if (ImGui::MenuItem("Save scene as...")) state.prompt = FilePrompt::SaveAs;
        ImGui::Separator();
        if (ImGui::MenuItem("Export paths (JSONL)...", nullptr, false, state.trace.has_value())) {
            state.prompt = FilePrompt::ExportPaths;
        }
        if (ImGui::MenuItem("Screenshot...")) state.prompt = FilePrompt::Screenshot;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.quit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const std::string undoText = state.document->canUndo() ? "Undo " + state.document->undoLabel() : "Undo";
        const std::string redoText = state.document->canRedo() ? "Redo " + state.document->redoLabel() : "Redo";
        if (ImGui::MenuItem(undoText.c_str(), "Ctrl+Z", false, state.document->canUndo())) undo(state);
        if (ImGui::MenuItem(redoText.c_str(), "Ctrl+Y", false, state.document->canRedo())) redo(state);
        if (ImGui::MenuItem("Delete selected", "Delete", false, state.selected != RayHit::kNone)) deleteSelected(state);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Fit to scene", "F")) state.fitRequested = true;
        ImGui::MenuItem("Octree cells", "C", &state.layers.octree);
        ImGui::MenuItem("Slice plane", "L", &state.slice.enabled);
        ImGui::MenuItem("Sources", nullptr, &state.layers.sources);
        ImGui::MenuItem("Paths", nullptr, &state.layers.paths);
        ImGui::MenuItem("Ray tree", nullptr, &state.layers.rayTree);
        ImGui::MenuItem("Event markers", nullptr, &state.layers.markers);
        ImGui::MenuItem("Axes", nullptr, &state.layers.axes);
        ImGui::MenuItem("Grid", nullptr, &state.layers.grid);
        ImGui::MenuItem("Translucent shapes", nullptr, &state.layers.render.translucent);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts and mouse", "F1")) state.showHelp = true;
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace dropscope::gui
