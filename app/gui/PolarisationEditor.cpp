#include "gui/PolarisationEditor.hpp"

#include "gui/SourceReference.hpp"
#include "render/PolarisationEllipse.hpp"

#include <imgui.h>

#include <array>
#include <numbers>

namespace dropscope::gui {

namespace {

constexpr std::array<const char*, 3> kKinds{"unpolarised", "linear", "Stokes vector"};  // PolarisationKind

// The kind chosen, carrying the state over where it can: linear light becomes its Stokes vector, and a
// Stokes vector becomes linear light along its ellipse's major axis.
void changeKind(SourcePolarisation& polarisation, PolarisationKind kind) {
    const PolarisationKind previous = polarisation.kind;
    if (kind == PolarisationKind::Stokes && previous == PolarisationKind::Linear) {
        polarisation.stokes = polarisation.unitStokes();
    }
    if (kind == PolarisationKind::Linear && previous == PolarisationKind::Stokes) {
        polarisation.linearDeg =
            render::polarisationEllipse(polarisation.stokes).orientation * 180.0 / std::numbers::pi;
    }
    polarisation.kind = kind;
}

bool inputStokes(const char* label, StokesVector& stokes) {
    std::array<double, 4> values{stokes[0], stokes[1], stokes[2], stokes[3]};
    if (!ImGui::InputScalarN(label, ImGuiDataType_Double, values.data(), 4, nullptr, nullptr, "%.4g")) return false;
    stokes = StokesVector(values[0], values[1], values[2], values[3]);
    return true;
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace

void polarisationEditor(Source& source, FieldEdits& edits, std::string& note, const ItemProbe& probe) {
    if (source.type == SourceType::PointSource) {
        ImGui::TextDisabled("polarisation: none (a point source is unpolarised)");
        return;
    }
    SourcePolarisation& polarisation = source.polarisation;
    int kind = static_cast<int>(polarisation.kind);
    if (edits.track(choiceCombo("polarisation", kind, kKinds, probe), "polarisation")) {
        changeKind(polarisation, static_cast<PolarisationKind>(kind));
        note = keepReferencePerpendicular(source);
    }
    if (polarisation.kind == PolarisationKind::Unpolarised) return;
    if (polarisation.kind == PolarisationKind::Linear) {
        edits.track(ImGui::InputDouble("angle (deg)", &polarisation.linearDeg, 1.0, 15.0, "%.4g"), "angle (deg)");
        reportItemRect(probe, "angle (deg)");
        tooltip("the field's direction, from the reference towards reference x direction");
    } else {
        edits.track(inputStokes("I Q U V", polarisation.stokes), "I Q U V");
        reportItemRect(probe, "I Q U V");
        tooltip(
            "Stokes vector (Bohren and Huffman): Q > 0 along the reference, U > 0 at +45 degrees from it\n"
            "towards reference x direction, V > 0 right-handed; Q^2 + U^2 + V^2 <= I^2");
    }
    edits.track(inputVector3("reference", polarisation.reference, "%.4g"), "reference");
    reportItemRect(probe, "reference");
    tooltip("the parallel axis of the frame the state is given in: perpendicular to the direction");
    if (edits.track(ImGui::Button("perpendicular reference"), "perpendicular reference")) {
        polarisation.reference = perpendicularReference(source.direction);
    }
    reportItemRect(probe, "perpendicular reference");
    tooltip("the coordinate axis least along the direction, made perpendicular to it");
}

}  // namespace dropscope::gui
