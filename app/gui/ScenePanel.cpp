#include "gui/Actions.hpp"
#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/ShapeDescription.hpp"
#include "scene/ShapeSpec.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace dropscope::gui {

namespace {

// What the shape list's filter box matches: "12 sphere d1 water".
std::string listLabel(const SceneDocument& document, ShapeId id, const Shape& shape) {
    std::string label = std::to_string(id) + " " + shapeTypeLabel(shape);
    if (!document.nameOf(id).empty()) label += " " + document.nameOf(id);
    return label + " " + document.media().at(shape.mediumId()).name;
}

void shapeList(AppState& state) {
    std::string& text = state.ui.panels.scenePanel.filter;
    ImGui::SetNextItemWidth(180.0f);
    ImGui::InputText("filter", &text);
    const ImGuiTextFilter filter(text.c_str());
    const SceneDocument& document = state.scene.document();
    const Octree& octree = document.octree();
    std::vector<ShapeId> shown;
    for (ShapeId id = 0; id < octree.slotCount(); ++id) {
        const Shape* shape = octree.shape(id);
        if (shape && (!filter.IsActive() || filter.PassFilter(listLabel(document, id, *shape).c_str())))
            shown.push_back(id);
    }
    ImGui::BeginChild("shapes", ImVec2(0.0f, 110.0f), true);
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(shown.size()));
    while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
            const ShapeId id = shown[static_cast<std::size_t>(row)];
            const std::string label = listLabel(document, id, *octree.shape(id));
            if (ImGui::Selectable(label.c_str(), id == state.scene.selectedShape())) state.scene.selectShape(id);
        }
    }
    ImGui::EndChild();
    ImGui::Text("%zu shown of %zu", shown.size(), document.shapeCount());
}

// The preset, its parameters and the matrix M of a parametric or implicit shape, read-only.
void generalShapeDetails(const GeneralShape& shape) {
    ImGui::Text("preset: %s", std::string(shape.presetName()).c_str());
    for (const PresetParameter& parameter : shape.presetParameters()) {
        ImGui::BulletText("%s: %s", parameter.key.c_str(), presetParameterText(parameter).c_str());
    }
    ImGui::TextUnformatted("matrix M, row by row:");
    for (const std::string& row : matrixRows(shape.transform().matrix())) ImGui::Text("  %s", row.c_str());
}

void selectedShapeEditor(AppState& state) {
    SceneDocument& document = state.scene.document();
    const ShapeId selected = state.scene.selectedShape();
    const Shape* shape = document.octree().shape(selected);
    if (!shape) {
        ImGui::TextDisabled("click a shape (or a row above) to edit it");
        return;
    }
    FieldEdits edits(state.ui.panels.scenePanel.editingItem);
    ShapeSpec spec = describeShape(*shape);
    ImGui::Text("shape %u: %s", selected, shapeTypeLabel(*shape).c_str());
    if (spec.kind == ShapeKind::Box) {
        edits.track(inputVector3("min", spec.boxMin), "min");
        edits.track(inputVector3("max", spec.boxMax), "max");
    } else if (spec.general) {
        // The base is shared and read-only here: only where it stands (r0) and its medium are edited.
        edits.track(inputVector3("centre", spec.center), "centre");
        reportItemRect(state.ui.itemProbe, "centre");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("the translation r0 of M r + r0");
    } else {
        edits.track(inputVector3("centre", spec.center), "centre");
        reportItemRect(state.ui.itemProbe, "centre");
        if (spec.kind == ShapeKind::Sphere) {
            edits.track(ImGui::InputDouble("radius", &spec.radius, 0.01, 0.1, "%.6g"), "radius");
        } else {
            edits.track(inputVector3("semi-axes", spec.semiAxes), "semi-axes");
            edits.track(inputVector3("rotation axis", spec.rotationAxis), "rotation axis");
            edits.track(ImGui::InputDouble("angle (deg)", &spec.rotationAngleDeg, 1.0, 10.0, "%.4g"), "angle (deg)");
        }
    }
    edits.track(mediumCombo("medium", document, spec.medium), "medium");
    if (spec.general) generalShapeDetails(*spec.general);  // below the fields, which stay in view
    if (edits.changed()) {
        state.ui.status.attempt("not changed", [&] {
            document.modifyShape(selected, spec, edits.continuesLast());
            edits.applied();
        });
    }
    edits.finish();
    if (ImGui::Button("Delete")) deleteSelected(state);
}

void addButtons(AppState& state) {
    const glm::dvec3 target = state.view.camera.target;
    const double radius = state.placement.radius;
    ShapeSpec spec;
    spec.center = Point(target.x, target.y, target.z);
    spec.radius = radius;
    spec.semiAxes = Eigen::Vector3d(1.5, 1.0, 0.7) * radius;
    spec.boxMin = spec.center - Eigen::Vector3d::Constant(2.0 * radius);
    spec.boxMax = spec.center + Eigen::Vector3d::Constant(2.0 * radius);
    spec.medium = state.placement.medium;
    const std::array<std::pair<const char*, ShapeKind>, 3> kinds{
        {{"Add sphere", ShapeKind::Sphere}, {"Add ellipsoid", ShapeKind::Ellipsoid}, {"Add box", ShapeKind::Box}}};
    for (const auto& [label, kind] : kinds) {
        if (ImGui::Button(label)) {
            spec.kind = kind;
            state.ui.status.attempt("not added", [&] {
                const ShapeId id = state.scene.document().addShape(spec);
                state.scene.selectShape(id);
                state.ui.status.say("added shape " + std::to_string(id) + " at the view's target");
            });
        }
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

void cloudGenerator(AppState& state) {
    if (!ImGui::TreeNode("Generate droplet cloud")) return;
    CloudFields& cloud = state.ui.panels.scenePanel.cloud;
    inputVector3("region min", cloud.lower);
    inputVector3("region max", cloud.upper);
    ImGui::InputInt("count", &cloud.count);
    ImGui::InputDouble("radius min", &cloud.radiusMin, 0.0, 0.0, "%.4g");
    ImGui::InputDouble("radius max", &cloud.radiusMax, 0.0, 0.0, "%.4g");
    ImGui::InputInt("seed", &cloud.seed);
    if (ImGui::Button("Region = scene bounds")) {
        Eigen::AlignedBox3d box;
        for (const auto& shape : state.scene.document().octree().shapes()) {
            if (shape) box.extend(shape->bounds());
        }
        if (!box.isEmpty()) {
            cloud.lower = box.min();
            cloud.upper = box.max();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Generate")) {
        state.ui.status.attempt("no cloud", [&] {
            if (cloud.count < 0) throw std::invalid_argument("count must be >= 0");
            if (!(cloud.radiusMin > 0.0) || !(cloud.radiusMax >= cloud.radiusMin))
                throw std::invalid_argument("need 0 < radius min <= radius max");
            if (!(cloud.lower.array() < cloud.upper.array()).all())
                throw std::invalid_argument("region min must be below max on every axis");
            DropletCloudSpec spec;
            spec.region = Eigen::AlignedBox3d(cloud.lower, cloud.upper);
            spec.count = static_cast<std::uint64_t>(cloud.count);
            spec.radius = cloud.radiusMax > cloud.radiusMin
                              ? RadiusDistribution::uniform(cloud.radiusMin, cloud.radiusMax)
                              : RadiusDistribution::fixed(cloud.radiusMin);
            spec.seed = static_cast<std::uint64_t>(std::max(cloud.seed, 0));
            const auto ids = state.scene.document().generateCloud(spec, state.placement.medium);
            state.ui.status.say("generated " + std::to_string(ids.size()) + " droplets" +
                                (ids.size() < static_cast<std::size_t>(cloud.count) ? " (the region filled up)" : ""));
        });
    }
    ImGui::TreePop();
}

}  // namespace

void drawScenePanel(AppState& state) {
    placeNextPanel(PanelSide::Left, 0.0f, 0.36f);
    if (!ImGui::Begin("Scene")) {
        ImGui::End();
        return;
    }
    shapeList(state);
    ImGui::Separator();
    selectedShapeEditor(state);
    ImGui::Separator();
    addButtons(state);
    cloudGenerator(state);
    ImGui::End();
}

}  // namespace dropscope::gui
