#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/TraceActions.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace dropscope::gui {

namespace {

constexpr const char* kSourceTypes[] = {"beam", "pencil (ray)", "point"};
// Photons per click: the UI stays responsive at any count (the trace runs on its own thread), but a
// recorded path costs memory and drawing, so those are capped.
constexpr std::uint64_t kMaxPhotons = 1'000'000'000;
constexpr std::uint64_t kMaxPaths = 100'000;

void sourceEditor(AppState& state) {
    SceneState& scene = state.scene;
    std::vector<Source> sources = scene.document().sources();
    if (!sources.empty()) scene.selectSource(scene.selectedSource());
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const std::string label = "source " + std::to_string(k) + ": " + std::string(sourceTypeName(sources[k].type));
        if (ImGui::Selectable(label.c_str(), k == scene.selectedSource())) scene.selectSource(k);
    }
    bool changed = false;
    if (!sources.empty()) {
        Source& source = sources[scene.selectedSource()];
        int type = static_cast<int>(source.type);
        if (ImGui::Combo("type", &type, kSourceTypes, 3)) {
            source.type = static_cast<SourceType>(type);
            if (source.type == SourceType::Beam && !(source.radius > 0.0)) source.radius = 0.5;
            changed = true;
        }
        changed |= inputVector3("origin (G)", source.origin, "%.5g");
        Point direction = source.direction.vector();
        if (inputVector3("direction (A)", direction, "%.5g")) {
            if (Direction(direction)) {
                source.direction = Direction(direction);
                changed = true;
            } else {
                state.ui.status.refuse("a direction must be a non-zero vector");
            }
        }
        if (source.type == SourceType::Beam) {
            changed |= ImGui::InputDouble("beam radius", &source.radius, 0.05, 0.5, "%.4g");
            source.radius = std::max(source.radius, 1e-9);
        }
    }
    if (ImGui::Button("Add source")) {
        const render::Camera& camera = state.view.camera;
        Source source;
        source.origin = Point(camera.eye.x, camera.eye.y, camera.eye.z);
        source.direction = Direction(Point(camera.target.x, camera.target.y, camera.target.z) - source.origin);
        sources.push_back(source);
        scene.selectSource(sources.size() - 1);
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Remove source") && !sources.empty()) {
        sources.erase(sources.begin() + static_cast<std::ptrdiff_t>(scene.selectedSource()));
        scene.selectSource(0);
        changed = true;
    }
    if (changed)
        state.ui.status.attempt("source not changed", [&] { scene.document().setSources(std::move(sources)); });
}

void fireControls(AppState& state) {
    FireSettings& fire = state.traces.fire;
    const std::uint64_t one = 1;
    ImGui::InputScalar("photons", ImGuiDataType_U64, &fire.photons, &one);
    ImGui::InputScalar("paths kept", ImGuiDataType_U64, &fire.paths, &one);
    ImGui::InputScalar("seed", ImGuiDataType_U64, &fire.seed, &one);
    fire.photons = std::clamp<std::uint64_t>(fire.photons, 1, kMaxPhotons);
    fire.paths = std::min(fire.paths, kMaxPaths);
    ImGui::Checkbox("live: trace again when the scene changes", &fire.live);
    if (ImGui::Button("Fire photons (Space)")) fireTrace(state);
    ImGui::SameLine();
    if (ImGui::Button("Fire ray tree (R)")) fireRayTree(state);
    if (state.traces.job.running()) drawTraceProgress(state, ImGui::GetContentRegionAvail().x - 60.0f);
}

}  // namespace

void drawFirePanel(AppState& state) {
    placeNextPanel(PanelSide::Right, 0.0f, 0.40f);
    if (!ImGui::Begin("Fire")) {
        ImGui::End();
        return;
    }
    sourceEditor(state);
    ImGui::Separator();
    fireControls(state);
    ImGui::End();
}

}  // namespace dropscope::gui
