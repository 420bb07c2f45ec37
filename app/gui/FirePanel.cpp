#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/Panels.hpp"
#include "gui/PolarisationEditor.hpp"
#include "gui/SourceReference.hpp"
#include "gui/SpectrumEditor.hpp"
#include "gui/TraceActions.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dropscope::gui {

namespace {

constexpr const char* kSourceTypes[] = {"beam", "pencil (ray)", "point"};
constexpr std::array<const char*, 2> kPolarisationModels{"Stokes vectors", "none (unpolarised Fresnel)"};
constexpr const char* kPolarisationHelp =
    "Stokes vectors: each photon and ray-tree branch carries its polarisation through every interface\n"
    "(the Fresnel amplitudes); none: every reflection has the unpolarised R = (Rs + Rp)/2";
// Photons per click: the UI stays responsive at any count (the trace runs on its own thread), but a
// recorded path costs memory and drawing, so those are capped.
constexpr std::uint64_t kMaxPhotons = 1'000'000'000;
constexpr std::uint64_t kMaxPaths = 100'000;
// Wavelength bands of the Results plot: 180 angular bins each, so kept to a few dozen curves.
constexpr int kMaxWavelengthBins = 24;
constexpr float kBinsFieldWidth = 150.0f;
constexpr const char* kDiffractionHelp =
    "Fraunhofer diffraction (trace --diffraction fraunhofer): spheres and ellipsoids also diffract the photons\n"
    "passing close by (a ring as large as their outline) into their Airy pattern, so a droplet's extinction\n"
    "is twice its cross-section and the forward peak of Mie theory appears; paths show 'diffract' events";
constexpr const char* kWavelengthBinsHelp =
    "bands of equal width over the sources' wavelengths, each with its angular distribution in the\n"
    "Results plot (angular_spectral.csv's bands); 1, or light of one wavelength: none";

// The selected source's type, place, aim, beam radius, polarisation, spectrum and divergence, edited in
// `source`; `note` gets what an edit changed besides its field, `refusal` why an edit cannot be made.
void sourceFields(AppState& state, Source& source, FieldEdits& edits, std::string& note, std::string& refusal) {
    int type = static_cast<int>(source.type);
    if (edits.track(ImGui::Combo("type", &type, kSourceTypes, 3), "type")) {
        source.type = static_cast<SourceType>(type);
        if (source.type == SourceType::Beam && !(source.radius > 0.0)) source.radius = 0.5;
        if (source.type == SourceType::PointSource && source.polarisation.kind != PolarisationKind::Unpolarised) {
            source.polarisation.kind = PolarisationKind::Unpolarised;
            note = "a point source is unpolarised: its polarisation was dropped";
        }
        if (source.type == SourceType::PointSource && source.divergenceDeg != 0.0) {
            source.divergenceDeg = 0.0;
            note += std::string(note.empty() ? "" : "; ") + "a point source is isotropic: its divergence was dropped";
        }
    }
    edits.track(inputVector3("origin (G)", source.origin, "%.5g"), "origin (G)");
    Point direction = source.direction.vector();
    // Applied on Enter: the direction stored is normalised, and a field still being typed in would apply
    // its text again every frame, as long as it differs from the normalised value shown.
    if (inputVector3("direction (A)", direction, "%.5g", ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (Direction(direction)) {
            edits.track(true, "direction (A)");
            note = aimSource(source, Direction(direction));
        } else {
            state.ui.status.refuse("a direction must be a non-zero vector");
        }
    }
    reportItemRect(state.ui.itemProbe, "direction (A)");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enter applies; the direction is normalised");
    if (source.type == SourceType::Beam) {
        edits.track(ImGui::InputDouble("beam radius", &source.radius, 0.05, 0.5, "%.4g"), "beam radius");
        source.radius = std::max(source.radius, 1e-9);
    }
    polarisationEditor(source, edits, note, state.ui.itemProbe);
    spectrumEditor(source, state.scene.document().wavelengthNm(), edits, refusal, state.ui.itemProbe);
}

// The sources, the selected one's fields, add and remove; every edit goes to the document as one undo
// step per field activation.
void sourceEditor(AppState& state) {
    SceneState& scene = state.scene;
    std::vector<Source> sources = scene.document().sources();
    if (!sources.empty()) scene.selectSource(scene.selectedSource());
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const std::string label = "source " + std::to_string(k) + ": " + std::string(sourceTypeName(sources[k].type));
        if (ImGui::Selectable(label.c_str(), k == scene.selectedSource())) scene.selectSource(k);
    }
    FieldEdits edits(state.ui.panels.firePanel.editingItem);
    std::string note;
    std::string refusal;
    if (!sources.empty()) sourceFields(state, sources[scene.selectedSource()], edits, note, refusal);
    if (edits.track(ImGui::Button("Add source"), "Add source")) {
        const render::Camera& camera = state.view.camera;
        Source source;
        source.origin = Point(camera.eye.x, camera.eye.y, camera.eye.z);
        source.direction = Direction(Point(camera.target.x, camera.target.y, camera.target.z) - source.origin);
        sources.push_back(source);
        scene.selectSource(sources.size() - 1);
    }
    ImGui::SameLine();
    if (edits.track(ImGui::Button("Remove source") && !sources.empty(), "Remove source")) {
        sources.erase(sources.begin() + static_cast<std::ptrdiff_t>(scene.selectedSource()));
        scene.selectSource(0);
    }
    if (!refusal.empty()) {
        state.ui.status.refuse("source not changed: " + refusal);
    } else if (edits.changed()) {
        state.ui.status.attempt("source not changed", [&] {
            scene.document().setSources(std::move(sources), edits.continuesLast());
            edits.applied();
            if (!note.empty()) state.ui.status.say(note);
        });
    }
    edits.finish();
}

void fireControls(AppState& state) {
    FireSettings& fire = state.traces.fire;
    const std::uint64_t one = 1;
    ImGui::InputScalar("photons", ImGuiDataType_U64, &fire.photons, &one);
    ImGui::InputScalar("paths kept", ImGuiDataType_U64, &fire.paths, &one);
    ImGui::InputScalar("seed", ImGuiDataType_U64, &fire.seed, &one);
    fire.photons = std::clamp<std::uint64_t>(fire.photons, 1, kMaxPhotons);
    fire.paths = std::min(fire.paths, kMaxPaths);
    int model = static_cast<int>(fire.polarisation);  // PolarisationModel: Stokes, None
    if (choiceCombo("trace with", model, kPolarisationModels, state.ui.itemProbe, kPolarisationHelp)) {
        fire.polarisation = static_cast<PolarisationModel>(model);
    }
    ImGui::SetNextItemWidth(kBinsFieldWidth);  // narrower than the others: room for its label
    ImGui::InputInt("wavelength bins", &fire.wavelengthBins);
    fire.wavelengthBins = std::clamp(fire.wavelengthBins, 1, kMaxWavelengthBins);
    reportItemRect(state.ui.itemProbe, "wavelength bins");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kWavelengthBinsHelp);
    ImGui::Checkbox("diffraction", &fire.diffraction);
    reportItemRect(state.ui.itemProbe, "diffraction");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kDiffractionHelp);
    ImGui::Checkbox("live: trace again when the scene changes", &fire.live);
    if (ImGui::Button("Fire photons (Space)")) fireTrace(state);
    ImGui::SameLine();
    if (ImGui::Button("Fire ray tree (R)")) fireRayTree(state);
    if (state.traces.job.running()) drawTraceProgress(state, ImGui::GetContentRegionAvail().x - 60.0f);
}

}  // namespace

void drawFirePanel(AppState& state) {
    placeNextPanel(PanelSide::Right, 0.0f, 0.56f);
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
