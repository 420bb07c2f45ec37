#include "gui/DispersionWindow.hpp"

#include "gui/PanelLayout.hpp"
#include "gui/PanelWidgets.hpp"
#include "gui/SpectralDrafts.hpp"
#include "gui/SpectralWidgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace dropscope::gui {

namespace {

constexpr float kWindowWidth = 360.0f;  // when first opened, beside the left column
constexpr float kWindowHeight = 330.0f;
constexpr float kPlotHeight = 90.0f;
constexpr float kBarHeight = 6.0f;   // the wavelength bar under the plot
constexpr int kPlotSamples = 161;    // 2.5 nm apart over the visible
constexpr double kRowStepNm = 50.0;  // a table's added row: 50 nm past the last
constexpr std::array<const char*, 3> kMaterials{"water", "bk7", "fused_silica"};  // Material's order
constexpr const char* kCauchyHelp = "n = c0 + c1/lambda^2 + c2/lambda^4 + ..., lambda in um";
constexpr const char* kSellmeierHelp = "n^2 = 1 + sum B lambda^2/(lambda^2 - C), lambda in um; rows B, C (um^2)";

const char* quantityName(OpticalQuantity quantity) {
    switch (quantity) {
    case OpticalQuantity::N: return "n";
    case OpticalQuantity::Kappa: return "kappa";
    case OpticalQuantity::Sigma: return "sigma";
    }
    return "?";
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string modelName(const SpectralFunction& model) {
    switch (model.kind()) {
    case SpectralFunction::Kind::Constant: return number(model.constantValue());
    case SpectralFunction::Kind::Table: return "table";
    case SpectralFunction::Kind::Cauchy: return "Cauchy";
    case SpectralFunction::Kind::Sellmeier: return "Sellmeier";
    case SpectralFunction::Kind::Builtin: {
        std::string name = materialName(model.material());
        if (model.material() == Material::Water && model.quantity() == OpticalQuantity::N) {
            name.append(" ").append(number(model.temperatureC())).append(" C");
        }
        return name;
    }
    }
    return "?";
}

// The form's choice and its numbers; true when the draft changed.
bool quantityEditor(OpticalQuantity quantity, ModelDraft& draft, const std::optional<SpectralFunction>& model,
                    double sceneWavelengthNm, const ItemProbe& probe) {
    const std::string name = quantityName(quantity);
    const std::span<const ModelForm> forms = formsOf(quantity);
    std::vector<const char*> names;
    for (const ModelForm form : forms) names.push_back(formName(form));
    int chosen = static_cast<int>(std::find(forms.begin(), forms.end(), draft.form) - forms.begin());
    bool changed = false;
    if (choiceCombo((name + " form").c_str(), chosen, names, probe)) {
        draft = startDraft(forms[static_cast<std::size_t>(chosen)], model, draft.number, sceneWavelengthNm);
        changed = true;
    }
    const std::string rows = name + " rows";
    switch (draft.form) {
    case ModelForm::Number:
        changed |=
            ImGui::InputDouble(name.c_str(), &draft.number, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
        reportItemRect(probe, name);
        break;
    case ModelForm::Table:
        ImGui::TextDisabled("rows: wavelength (nm), %s", name.c_str());
        changed |= editRows(rows.c_str(), draft.rows, 2, {kVisibleRangeNm[0], draft.number}, kRowStepNm, probe);
        break;
    case ModelForm::Cauchy:
        ImGui::TextDisabled("%s", kCauchyHelp);
        changed |= editRows(rows.c_str(), draft.rows, 1, {0.0, 0.0}, 0.0, probe);
        break;
    case ModelForm::Sellmeier:
        ImGui::TextDisabled("%s", kSellmeierHelp);
        changed |= editRows(rows.c_str(), draft.rows, 2, {0.0, 0.0}, 0.0, probe);
        break;
    case ModelForm::Builtin:
        if (quantity != OpticalQuantity::N) {
            ImGui::TextDisabled("water: Hale and Querry (1973), 25 C, 200-2600 nm");
            break;
        }
        int material = static_cast<int>(draft.material);
        if (choiceCombo("material", material, kMaterials, probe)) {
            draft.material = static_cast<Material>(material);
            changed = true;
        }
        if (draft.material == Material::Water) {
            changed |= ImGui::InputDouble("temperature (C)", &draft.temperatureC, 0.0, 0.0, "%.4g",
                                          ImGuiInputTextFlags_EnterReturnsTrue);
            reportItemRect(probe, "temperature (C)");
        }
        break;
    }
    return changed;
}

// The medium with `quantity` given as `draft`, to the document; refused in the status line when the draft
// is not a valid model or the document refuses the medium.
void applyDraft(SceneDocument& document, MediumId id, OpticalQuantity quantity, const ModelDraft& draft,
                StatusLine& status) {
    status.attempt("medium not changed", [&] {
        Medium medium = document.media()[id];
        const std::optional<SpectralFunction> model = modelOf(draft, quantity);
        switch (quantity) {
        case OpticalQuantity::N:
            medium.nModel = model;
            if (!model) medium.n = draft.number;
            break;
        case OpticalQuantity::Kappa:
            medium.kappaModel = model;
            medium.kappa = model ? medium.kappa.value_or(0.0) : draft.number;  // a model's value: set by the document
            break;
        case OpticalQuantity::Sigma:
            medium.sigmaModel = model;
            medium.sigma = model ? medium.sigma.value_or(0.0) : draft.number;
            break;
        }
        document.setMedium(id, medium);
        status.say("medium " + medium.name + ": " + quantityName(quantity) + " " +
                   (model ? modelName(*model) : number(draft.number)));
    });
}

// Where n is plotted: the visible range within the model's domain (the domain itself when they do not meet).
std::array<double, 2> plotRange(const Medium& medium) {
    std::array<double, 2> range = kVisibleRangeNm;
    const auto domain = medium.nModel ? medium.nModel->domainNm() : std::nullopt;
    if (!domain) return range;
    range = {std::max(range[0], domain->first), std::min(range[1], domain->second)};
    if (!(range[0] < range[1])) range = {domain->first, domain->second};
    return range;
}

// n against the wavelength, the wavelength bar under it, the values at the ends in words; the value under
// the mouse in a tooltip.
void nPlot(const Medium& medium, const ItemProbe& probe) {
    const auto [lo, hi] = plotRange(medium);
    std::vector<double> values;
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (int k = 0; k < kPlotSamples; ++k) {
        const double nm = lo + (hi - lo) * k / (kPlotSamples - 1);
        double value = std::nan("");
        try {
            value = medium.nModel ? medium.nModel->at(nm) : medium.n;
        } catch (const std::exception&) {
            // a Sellmeier pole: a gap
        }
        values.push_back(value);
        if (std::isfinite(value)) {
            low = std::min(low, value);
            high = std::max(high, value);
        }
    }
    const double pad = std::max(1e-4, 0.05 * (high - low));
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + width, at.y + kPlotHeight), ImGui::GetColorU32(ImGuiCol_FrameBg));
    std::vector<ImVec2> line;
    for (int k = 0; k < kPlotSamples; ++k) {
        const double value = values[static_cast<std::size_t>(k)];
        if (!std::isfinite(value)) continue;
        line.emplace_back(at.x + width * static_cast<float>(k) / (kPlotSamples - 1),
                          at.y + kPlotHeight * static_cast<float>((high + pad - value) / (high - low + 2.0 * pad)));
    }
    draw->AddPolyline(line.data(), static_cast<int>(line.size()), ImGui::GetColorU32(ImGuiCol_PlotLines), 0, 1.5f);
    ImGui::InvisibleButton("n plot", ImVec2(width, kPlotHeight));
    if (ImGui::IsItemHovered()) {
        const float t = std::clamp((ImGui::GetIO().MousePos.x - at.x) / width, 0.0f, 1.0f);
        const auto k = static_cast<std::size_t>(std::lround(t * (kPlotSamples - 1)));
        ImGui::SetTooltip("%.1f nm: n %.6g", lo + (hi - lo) * static_cast<double>(k) / (kPlotSamples - 1), values[k]);
    }
    wavelengthBar(lo, hi, width, kBarHeight);
    const std::string ends = "n " + number(values.front()) + " at " + number(lo) + " nm, " + number(values.back()) +
                             " at " + number(hi) + " nm";
    probedText(probe, "n plot range", ends);
}

}  // namespace

std::string dispersionSummary(const Medium& medium) {
    if (!medium.dispersive()) return "number";
    std::string text;
    const auto add = [&](const char* name, const std::optional<SpectralFunction>& model) {
        if (!model) return;
        if (!text.empty()) text += ", ";
        text.append(name).append(" ").append(modelName(*model));
    };
    add("n", medium.nModel);
    add("kappa", medium.kappaModel);
    add("sigma", medium.sigmaModel);
    return text;
}

void drawDispersionWindow(SceneDocument& document, MediaPanelFields& fields, StatusLine& status,
                          const ItemProbe& probe) {
    if (!fields.dispersionOpen) return;
    if (fields.dispersionOf >= document.media().size()) {  // undone: the medium is gone
        fields.dispersionOpen = false;
        return;
    }
    const MediumId id = fields.dispersionOf;
    const Medium medium = document.media()[id];  // a copy: an edit replaces the document's
    const double sceneNm = document.wavelengthNm();
    ImGui::SetNextWindowPos(ImVec2(kPanelWidth + 10.0f, kMenuHeight + 40.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kWindowWidth, kWindowHeight), ImGuiCond_FirstUseEver);
    const std::string title = "Dispersion: " + medium.name + "###Dispersion";
    if (ImGui::Begin(title.c_str(), &fields.dispersionOpen)) {
        ImGui::TextDisabled("n %.6g at the scene's %s; Enter applies", medium.n, formatWavelength(sceneNm).c_str());
        ModelDraft n = draftOf(medium.nModel, medium.n);
        if (quantityEditor(OpticalQuantity::N, n, medium.nModel, sceneNm, probe)) {
            applyDraft(document, id, OpticalQuantity::N, n, status);
        }
        nPlot(document.media()[id], probe);
        ImGui::Separator();
        const bool sigma = medium.sigma.has_value();
        const OpticalQuantity absorption = sigma ? OpticalQuantity::Sigma : OpticalQuantity::Kappa;
        const std::optional<SpectralFunction>& model = sigma ? medium.sigmaModel : medium.kappaModel;
        ModelDraft draft = draftOf(model, sigma ? *medium.sigma : medium.kappa.value_or(0.0));
        if (quantityEditor(absorption, draft, model, sceneNm, probe)) {
            applyDraft(document, id, absorption, draft, status);
        }
    }
    ImGui::End();
}

}  // namespace dropscope::gui
