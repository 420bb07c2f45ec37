#include "gui/Shortcuts.hpp"

#include "gui/Actions.hpp"
#include "gui/TraceActions.hpp"
#include "gui/platform/InputFrame.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>

namespace dropscope::gui {

namespace {

void toggleHelp(AppState& state) { state.ui.showHelp = !state.ui.showHelp; }
void screenshotNow(AppState& state) {
    state.ui.screenshot = ScreenshotRequest{
        timestampedScreenshotPath(state.ui.screenshotDirectory, std::chrono::system_clock::now()), false, 0, 0};
}
void save(AppState& state) {
    if (state.scene.file().empty()) {
        state.ui.status.refuse("no file yet: use File > Save as");
        return;
    }
    saveScene(state, state.scene.file());
}
void askOpen(AppState& state) { state.ui.prompt = FilePrompt::Open; }
void quit(AppState& state) { state.ui.quit = true; }
void togglePlacement(AppState& state) {
    bool& active = state.placement.active;
    active = !active;
    state.ui.status.say(active ? "placement mode: click to drop a droplet (P or Esc to leave)" : "placement mode off");
}
void escape(AppState& state) {
    if (state.traces.job.running()) return cancelTrace(state);
    if (state.placement.active) return togglePlacement(state);
    state.scene.selectShape(RayHit::kNone);
}
void fit(AppState& state) { state.view.fitRequested = true; }
void toggleSlice(AppState& state) { state.view.slice.enabled = !state.view.slice.enabled; }
void toggleOctree(AppState& state) { state.view.layers.octree = !state.view.layers.octree; }
void octreeLevel(AppState& state, int delta) {
    render::LayerOptions& layers = state.view.layers;
    layers.octree = true;
    const int deepest = std::max(0, static_cast<int>(state.scene.document().octree().statistics().size()) - 1);
    layers.octreeFilter.level = std::clamp(layers.octreeFilter.level + delta, 0, deepest);
}
void levelDown(AppState& state) { octreeLevel(state, -1); }
void levelUp(AppState& state) { octreeLevel(state, +1); }
void previousEvent(AppState& state) { stepEvent(state.traces, -1); }
void nextEvent(AppState& state) { stepEvent(state.traces, +1); }

}  // namespace

const std::vector<Shortcut>& shortcuts() {
    static const std::vector<Shortcut> table{
        {kKeyF1, false, false, "F1", "show or hide this help", toggleHelp},
        {kKeyF12, false, false, "F12", "screenshot of the 3D view: dropscope-DATE-TIME.png in the working directory",
         screenshotNow},
        {'Z', true, false, "Ctrl+Z", "undo", undo},
        {'Y', true, false, "Ctrl+Y", "redo", redo},
        {'Z', true, true, "Ctrl+Shift+Z", "redo", redo},
        {'S', true, false, "Ctrl+S", "save the scene", save},
        {'O', true, false, "Ctrl+O", "open a scene", askOpen},
        {'Q', true, false, "Ctrl+Q", "quit", quit},
        {'P', false, false, "P", "placement mode on/off: a click drops a droplet", togglePlacement},
        {kKeySpace, false, false, "Space", "fire the photons of the Fire panel (Monte Carlo)", fireTrace},
        {'R', false, false, "R", "fire the selected source's ray as a ray tree", fireRayTree},
        {kKeyEscape, false, false, "Esc", "cancel the trace, leave placement mode, or clear the selection", escape},
        {kKeyDelete, false, false, "Delete", "delete the selected shape", deleteSelected},
        {'F', false, false, "F", "fit the view to the scene", fit},
        {'L', false, false, "L", "slice plane on/off", toggleSlice},
        {'C', false, false, "C", "octree cells on/off", toggleOctree},
        {'[', false, false, "[", "octree level down", levelDown},
        {']', false, false, "]", "octree level up", levelUp},
        {kKeyLeft, false, false, "Left", "previous event of the selected path", previousEvent},
        {kKeyRight, false, false, "Right", "next event of the selected path", nextEvent},
        {'G', false, false, "G", "move the selected source (or detector) to the point under the cursor", nullptr},
        {'A', false, false, "A", "aim the selected source (or detector) at the point under the cursor", nullptr},
    };
    return table;
}

const std::vector<std::pair<std::string_view, std::string_view>>& mouseGestures() {
    static const std::vector<std::pair<std::string_view, std::string_view>> table{
        {"left drag", "orbit about the target"},
        {"right or middle drag", "pan"},
        {"wheel", "zoom"},
        {"click", "select the shape under the cursor (through glass boxes)"},
        {"drag the selected droplet", "move it (refused where it would overlap)"},
        {"drag the source's white handle", "move the selected source"},
        {"drag the source's orange handle", "aim the selected source"},
        {"drag a detector's white or blue handle", "move or aim the detector selected in the Detectors panel"},
        {"click in placement mode", "drop a droplet on the surface under the cursor, else on the placement plane"},
        {"hover", "tooltip: id, type, medium"},
    };
    return table;
}

void handleShortcuts(AppState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || state.ui.prompt != FilePrompt::None) return;  // keys belong to the field or dialog
    for (const Shortcut& shortcut : shortcuts()) {
        if (!shortcut.run || shortcut.ctrl != io.KeyCtrl || shortcut.shift != io.KeyShift) continue;
        if (ImGui::IsKeyPressed(shortcut.key, false)) shortcut.run(state);
    }
}

}  // namespace dropscope::gui
