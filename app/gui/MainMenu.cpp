#include "gui/Actions.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

namespace dropscope::gui {

void drawMainMenu(AppState& state) {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        FilePrompt& prompt = state.ui.prompt;
        const std::filesystem::path& file = state.scene.file();
        if (ImGui::MenuItem("Open scene...", "Ctrl+O")) prompt = FilePrompt::Open;
        if (ImGui::MenuItem("Save scene", "Ctrl+S", false, !file.empty())) saveScene(state, file);
        if (ImGui::MenuItem("Save scene as...")) prompt = FilePrompt::SaveAs;
        ImGui::Separator();
        if (ImGui::MenuItem("Export paths (JSONL)...", nullptr, false, state.traces.trace.has_value())) {
            prompt = FilePrompt::ExportPaths;
        }
        if (ImGui::MenuItem("Screenshot...")) prompt = FilePrompt::Screenshot;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.ui.quit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const SceneDocument& document = state.scene.document();
        const std::string undoText = document.canUndo() ? "Undo " + document.undoLabel() : "Undo";
        const std::string redoText = document.canRedo() ? "Redo " + document.redoLabel() : "Redo";
        if (ImGui::MenuItem(undoText.c_str(), "Ctrl+Z", false, document.canUndo())) undo(state);
        if (ImGui::MenuItem(redoText.c_str(), "Ctrl+Y", false, document.canRedo())) redo(state);
        if (ImGui::MenuItem("Delete selected", "Delete", false, state.scene.selectedShape() != RayHit::kNone)) {
            deleteSelected(state);
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        ViewState& view = state.view;
        if (ImGui::MenuItem("Fit to scene", "F")) view.fitRequested = true;
        ImGui::MenuItem("Octree cells", "C", &view.layers.octree);
        ImGui::MenuItem("Slice plane", "L", &view.slice.enabled);
        ImGui::MenuItem("Sources", nullptr, &view.layers.sources);
        ImGui::MenuItem("Detectors (and their panel)", nullptr, &view.layers.detectors);
        ImGui::MenuItem("Paths", nullptr, &view.layers.paths);
        ImGui::MenuItem("Ray tree", nullptr, &view.layers.rayTree);
        ImGui::MenuItem("Event markers", nullptr, &view.layers.markers);
        ImGui::MenuItem("Axes", nullptr, &view.layers.axes);
        ImGui::MenuItem("Grid", nullptr, &view.layers.grid);
        ImGui::MenuItem("Translucent shapes", nullptr, &view.layers.render.translucent);
        ImGui::MenuItem("Draw spheres and lines on the processor", nullptr, &view.layers.render.processorRaster);
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip(
                "Faster than a software OpenGL (llvmpipe, on by default there); a view holding\n"
                "other shapes, translucent ones or detector screens is drawn by OpenGL.");
        }
        ImGui::MenuItem("Draw the panels there too", nullptr, &state.ui.panelsOnProcessor);
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip(
                "The panels drawn into the view's picture when it is drawn on the processor;\n"
                "panels showing a plot or a detector's image are drawn by OpenGL.");
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts and mouse", "F1")) state.ui.showHelp = true;
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace dropscope::gui
