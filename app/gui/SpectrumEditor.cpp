#include "gui/SpectrumEditor.hpp"

#include "gui/SpectralDrafts.hpp"
#include "gui/SpectralWidgets.hpp"

#include <imgui.h>

#include <stdexcept>

namespace dropscope::gui {

namespace {

constexpr float kPreviewHeight = 28.0f;
constexpr float kPreviewWidth = 200.0f;
constexpr double kRowStepNm = 50.0;  // a table's added row: 50 nm past the last
constexpr const char* kSpectrumHelp =
    "the wavelengths the source's photons draw from; scene line: the scene's wavelength_nm\n"
    "sun: a 5778 K blackbody over 380-780 nm";
constexpr const char* kDivergenceHelp =
    "half-angle of the cone the directions are spread over, uniformly (the sun's disk: 0.266)";

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// The draft's numbers; true when one was edited.
bool draftFields(SpectrumDraft& draft, double sceneWavelengthNm, const ItemProbe& probe) {
    bool changed = false;
    switch (draft.form) {
    case SpectrumForm::SceneLine: ImGui::TextDisabled("one line at the scene's %.6g nm", sceneWavelengthNm); break;
    case SpectrumForm::Lines:
    case SpectrumForm::Table:
        ImGui::TextDisabled("rows: wavelength (nm), weight");
        changed |= editRows("spectrum rows", draft.rows, 2, {sceneWavelengthNm, 1.0},
                            draft.form == SpectrumForm::Table ? kRowStepNm : 0.0, probe);
        break;
    case SpectrumForm::Blackbody:
        changed |= ImGui::InputDouble("temperature (K)", &draft.kelvin, 0.0, 0.0, "%.6g",
                                      ImGuiInputTextFlags_EnterReturnsTrue);
        reportItemRect(probe, "temperature (K)");
        [[fallthrough]];
    case SpectrumForm::Uniform:
        changed |= ImGui::InputScalarN("range (nm)", ImGuiDataType_Double, draft.boundsNm.data(), 2, nullptr, nullptr,
                                       "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
        reportItemRect(probe, "range (nm)");
        break;
    case SpectrumForm::Sun:
        ImGui::TextDisabled("a %.0f K blackbody over %.0f-%.0f nm", kSunKelvin, kSunRangeNm.first, kSunRangeNm.second);
        break;
    }
    return changed;
}

}  // namespace

void spectrumEditor(Source& source, double sceneWavelengthNm, FieldEdits& edits, std::string& refusal,
                    const ItemProbe& probe) {
    SpectrumDraft draft = draftOf(source.spectrum);
    int form = static_cast<int>(draft.form);
    bool changed = false;
    if (edits.track(choiceCombo("spectrum", form, spectrumFormNames(), probe, kSpectrumHelp), "spectrum")) {
        draft = startDraft(static_cast<SpectrumForm>(form), source.spectrum, sceneWavelengthNm);
        changed = true;
    }
    changed |= edits.track(draftFields(draft, sceneWavelengthNm, probe), "spectrum fields");
    if (changed) {
        try {
            source.spectrum = spectrumOf(draft);
        } catch (const std::invalid_argument& error) {
            refusal = std::string("spectrum ") + spectrumFormNames()[static_cast<std::size_t>(draft.form)] + ": " +
                      error.what();
        }
    }
    spectrumPreview(sourceSpectrum(source, sceneWavelengthNm), kPreviewWidth, kPreviewHeight);
    if (source.type == SourceType::PointSource) {
        ImGui::TextDisabled("divergence: none (a point source is isotropic)");
        return;
    }
    edits.track(ImGui::InputDouble("divergence (deg)", &source.divergenceDeg, 0.1, 1.0, "%.4g"), "divergence (deg)");
    reportItemRect(probe, "divergence (deg)");
    tooltip(kDivergenceHelp);
}

}  // namespace dropscope::gui
