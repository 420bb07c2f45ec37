#include "gui/DetectorDefaults.hpp"
#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <array>
#include <cstdint>
#include <string>

namespace dropscope::gui {

namespace {

constexpr std::array<const char*, 3> kSides{"both", "front", "back"};
constexpr std::array<const char*, 3> kProjections{"equidistant", "equal_area", "perspective"};
constexpr const char* kSideHelp =
    "which crossings count: both directions, or only light arriving on the side the normal points to (front),\n"
    "or only on the other side (back); the arrow in the view points to the side counted";
constexpr const char* kEnterHelp = "Enter applies; a direction is normalised";

std::string detectorLabel(const Detector& detector) {
    std::string label = detector.name + ": " + std::string(detectorTypeName(detector.type));
    if (detector.type != DetectorType::ShapeAbsorption) {
        label += ", " + std::to_string(detector.pixels.nx) + " x " + std::to_string(detector.pixels.ny) + " pixels";
    }
    return label;
}

// A direction typed in, applied on Enter (a field still being typed would apply its text every frame, as
// FirePanel's direction); refused in the status line when it is zero.
void directionField(AppState& state, FieldEdits& edits, const char* label, Direction& direction) {
    Point typed = direction.vector();
    if (inputVector3(label, typed, "%.5g", ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (Direction(typed)) {
            direction = Direction(typed);
            edits.track(true, label);
        } else {
            state.ui.status.refuse("detector not changed: a direction must be a non-zero vector");
        }
    }
    reportItemRect(state.ui.itemProbe, label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kEnterHelp);
}

void upField(AppState& state, FieldEdits& edits, Eigen::Vector3d& up) {
    edits.track(inputVector3("up", up, "%.5g", ImGuiInputTextFlags_EnterReturnsTrue), "up");
    reportItemRect(state.ui.itemProbe, "up");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the image's v (up) direction, projected into its plane; Enter applies");
}

void pixelsField(AppState& state, FieldEdits& edits, PixelGrid& pixels) {
    int grid[2] = {pixels.nx, pixels.ny};
    if (edits.track(ImGui::InputInt2("pixels", grid, ImGuiInputTextFlags_EnterReturnsTrue), "pixels")) {
        pixels = {grid[0], grid[1]};
    }
    reportItemRect(state.ui.itemProbe, "pixels");
}

void planeFields(AppState& state, FieldEdits& edits, Detector& plane) {
    edits.track(inputVector3("center (G)", plane.center, "%.5g"), "center (G)");
    reportItemRect(state.ui.itemProbe, "center (G)");
    directionField(state, edits, "normal (A)", plane.normal);
    upField(state, edits, plane.up);
    edits.track(ImGui::InputScalarN("size", ImGuiDataType_Double, plane.size.data(), 2, nullptr, nullptr, "%.4g",
                                    ImGuiInputTextFlags_EnterReturnsTrue),
                "size");
    reportItemRect(state.ui.itemProbe, "size");
    pixelsField(state, edits, plane.pixels);
    int side = static_cast<int>(plane.side);  // DetectorSide: Both, Front, Back
    if (edits.track(choiceCombo("side", side, kSides, state.ui.itemProbe, kSideHelp), "side")) {
        plane.side = static_cast<DetectorSide>(side);
    }
    edits.track(ImGui::Checkbox("absorbing: ends the photons it counts", &plane.absorbing), "absorbing");
    reportItemRect(state.ui.itemProbe, "absorbing");
}

void farFieldFields(AppState& state, FieldEdits& edits, Detector& camera) {
    directionField(state, edits, "look (A)", camera.look);
    upField(state, edits, camera.up);
    int projection = static_cast<int>(camera.projection);  // FarFieldProjection: Equidistant, EqualArea, Perspective
    if (edits.track(choiceCombo("projection", projection, kProjections, state.ui.itemProbe), "projection")) {
        camera.projection = static_cast<FarFieldProjection>(projection);
    }
    edits.track(ImGui::InputDouble("fov (deg)", &camera.fovDeg, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue),
                "fov (deg)");
    reportItemRect(state.ui.itemProbe, "fov (deg)");
    pixelsField(state, edits, camera.pixels);
}

// The selected detector's fields, edited in `detector`.
void detectorFields(AppState& state, FieldEdits& edits, Detector& detector) {
    std::string name = detector.name;
    if (edits.track(ImGui::InputText("name", &name, ImGuiInputTextFlags_EnterReturnsTrue), "name")) {
        detector.name = name;
    }
    reportItemRect(state.ui.itemProbe, "name");
    if (detector.type == DetectorType::Plane) planeFields(state, edits, detector);
    if (detector.type == DetectorType::FarField) farFieldFields(state, edits, detector);
    const std::uint64_t one = 1;
    edits.track(ImGui::InputScalar("record hits", ImGuiDataType_U64, &detector.record, &one), "record hits");
}

void addButton(AppState& state, const char* label, DetectorType type) {
    const bool clicked = ImGui::Button(label);
    reportItemRect(state.ui.itemProbe, label);
    if (!clicked) return;
    SceneDocument& document = state.scene.document();
    const Detector detector = defaultDetector(document, type);
    state.ui.status.attempt("detector not added", [&] {
        document.addDetector(detector);
        state.scene.selectDetector(document.detectors().size() - 1);
        state.ui.status.say("added detector \"" + detector.name + "\"");
    });
}

}  // namespace

void drawDetectorsPanel(AppState& state) {
    if (!state.view.layers.detectors) return;
    placeNextPanel(PanelSide::Left, 0.36f, 0.43f);  // over the Media and Place panels, while it is open:
    ImGui::SetNextWindowBgAlpha(1.0f);              // opaque, so their fields do not show through
    if (!ImGui::Begin("Detectors", &state.view.layers.detectors)) {
        ImGui::End();
        return;
    }
    SceneState& scene = state.scene;
    const std::vector<Detector>& detectors = scene.document().detectors();
    const std::optional<std::size_t> selected = scene.selectedDetector();
    for (std::size_t k = 0; k < detectors.size(); ++k) {
        ImGui::PushID(static_cast<int>(k));
        if (ImGui::Selectable(detectorLabel(detectors[k]).c_str(), selected == k)) {
            scene.selectDetector(selected == k ? std::nullopt : std::optional<std::size_t>(k));  // a click again: none
        }
        reportItemRect(state.ui.itemProbe, "detector " + detectors[k].name);
        ImGui::PopID();
    }
    if (detectors.empty()) ImGui::TextDisabled("no detectors: add one");
    addButton(state, "Add plane", DetectorType::Plane);
    ImGui::SameLine();
    addButton(state, "Add far-field", DetectorType::FarField);
    ImGui::SameLine();
    addButton(state, "Add absorption", DetectorType::ShapeAbsorption);
    if (const auto index = scene.selectedDetector()) {
        ImGui::Separator();
        Detector detector = scene.document().detectors()[*index];
        FieldEdits edits(state.ui.panels.detectorsPanel.editingItem);
        detectorFields(state, edits, detector);
        if (edits.changed()) {
            state.ui.status.attempt("detector not changed", [&] {
                scene.document().setDetector(*index, detector, edits.continuesLast());
                edits.applied();
            });
        }
        edits.finish();
        const bool remove = ImGui::Button("Remove detector");
        reportItemRect(state.ui.itemProbe, "Remove detector");
        if (remove) {
            state.ui.status.attempt("detector not removed", [&] {
                const std::string name = detector.name;
                scene.document().removeDetector(*index);
                scene.selectDetector(std::nullopt);
                state.ui.status.say("removed detector \"" + name + "\"");
            });
        }
    }
    ImGui::End();
}

}  // namespace dropscope::gui
