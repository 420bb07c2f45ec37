#include "gui/PanelLayout.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace dropscope::gui {

namespace {

const std::vector<LevelStatistics>& levelStatistics(OctreeStatistics& cache, const SceneState& scene) {
    const SceneDocument& document = scene.document();
    if (cache.levels.empty() || cache.generation != scene.generation() || cache.revision != document.revision()) {
        cache.levels = document.octree().statistics();
        cache.generation = scene.generation();
        cache.revision = document.revision();
    }
    return cache.levels;
}

void statisticsTable(const std::vector<LevelStatistics>& statistics) {
    if (!ImGui::BeginTable("levels", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY,
                           ImVec2(0.0f, 130.0f))) {
        return;
    }
    ImGui::TableSetupColumn("level");
    ImGui::TableSetupColumn("cells");
    ImGui::TableSetupColumn("leaves");
    ImGui::TableSetupColumn("shapes stored");
    ImGui::TableHeadersRow();
    for (const LevelStatistics& level : statistics) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%d", level.level);
        ImGui::TableNextColumn();
        ImGui::Text("%zu", level.cells);
        ImGui::TableNextColumn();
        ImGui::Text("%zu", level.leaves);
        ImGui::TableNextColumn();
        ImGui::Text("%zu", level.shapesStored);
    }
    ImGui::EndTable();
}

void traversalList(const TraceState& traces, render::LayerOptions& layers) {
    if (!traces.traversal || !traces.trace) {
        ImGui::TextDisabled("select a path event (Paths panel) to see its segment's traversal");
        return;
    }
    const TraversalRecord& record = traces.traversal->record;
    ImGui::Checkbox("draw the traversal", &layers.traversal);
    // The traversal ran in the traced scene, whose ids are compact; the panel shows the document's.
    const auto& slots = traces.trace->slotOfShape;
    const auto slot = [&](ShapeId id) { return id < slots.size() ? slots[id] : id; };
    ImGui::Text("%zu cells visited, %zu shape tests, hit %s", record.cells.size(), record.shapesTested.size(),
                record.hit ? ("shape " + std::to_string(slot(record.hit.shape))).c_str() : "nothing");
    ImGui::BeginChild("visits", ImVec2(0.0f, 110.0f), true);
    for (std::size_t k = 0; k < record.cells.size(); ++k) {
        const CellVisit& visit = record.cells[k];
        ImGui::Text("%zu: level %d  [%.3g %.3g %.3g] - [%.3g %.3g %.3g]", k, visit.level, visit.bounds.min().x(),
                    visit.bounds.min().y(), visit.bounds.min().z(), visit.bounds.max().x(), visit.bounds.max().y(),
                    visit.bounds.max().z());
    }
    std::string tested;
    for (ShapeId id : record.shapesTested) tested += std::to_string(slot(id)) + " ";
    ImGui::TextWrapped("shapes tested: %s", tested.c_str());
    ImGui::EndChild();
}

}  // namespace

void drawOctreePanel(AppState& state) {
    placeNextPanel(PanelSide::Right, 0.56f, 0.30f);
    // Collapsed at first, under the Fire panel (the right column has no room for it beside the Paths
    // panel); it opens, in front, when the cells are switched on (C, the View menu).
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    bool& cellsShown = state.ui.panels.octreeCellsShown;
    if (state.view.layers.octree && !cellsShown) {
        ImGui::SetNextWindowCollapsed(false);
        ImGui::SetNextWindowFocus();
    }
    cellsShown = state.view.layers.octree;
    if (!ImGui::Begin("Octree")) {
        ImGui::End();
        return;
    }
    const std::vector<LevelStatistics>& statistics = levelStatistics(state.ui.panels.octreeStatistics, state.scene);
    const int deepest = std::max(0, static_cast<int>(statistics.size()) - 1);
    render::LayerOptions& layers = state.view.layers;
    render::OctreeFilter& filter = layers.octreeFilter;
    ImGui::Checkbox("show cells (C)", &layers.octree);
    bool changed = ImGui::SliderInt("depth ([ ])", &filter.level, 0, deepest);
    int mode = filter.mode == render::OctreeFilter::Mode::UpToLevel    ? 1
               : filter.mode == render::OctreeFilter::Mode::LeavesOnly ? 2
                                                                       : 0;
    changed |= ImGui::RadioButton("only level", &mode, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("up to level", &mode, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("leaves", &mode, 2);
    filter.mode = mode == 1   ? render::OctreeFilter::Mode::UpToLevel
                  : mode == 2 ? render::OctreeFilter::Mode::LeavesOnly
                              : render::OctreeFilter::Mode::OnlyLevel;
    changed |= ImGui::Checkbox("occupancy colour", &filter.occupancyColour);
    if (changed) layers.octree = true;  // moving a filter means: show me
    statisticsTable(statistics);
    ImGui::Separator();
    traversalList(state.traces, layers);
    ImGui::End();
}

}  // namespace dropscope::gui
