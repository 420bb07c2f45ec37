#pragma once

#include "spectrum/SpectralFunction.hpp"
#include "spectrum/Spectrum.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace dropscope::gui {

// A medium's dispersion model and a source's spectrum as the panels edit them: plain rows of numbers,
// made again from the document's model every frame, edited in place, then turned back into the model
// when applied. Turning them back may throw what the engine's factories throw (a table whose wavelengths
// do not ascend, ...): the panels do it inside StatusLine::attempt, so the refusal is shown and nothing
// changes. No ImGui here.

// How a medium's n, kappa or sigma is given in the Media panel's Dispersion window.
enum class ModelForm { Number, Table, Cauchy, Sellmeier, Builtin };

// What each quantity may be given as: n every form; kappa a number, a table or a built-in material's
// (water's); sigma a number or a table. In the order the form's combo lists them.
std::span<const ModelForm> formsOf(OpticalQuantity quantity);
// "number", "table", "Cauchy", "Sellmeier", "builtin".
const char* formName(ModelForm form);

struct ModelDraft {
    ModelForm form = ModelForm::Number;
    double number = 0.0;  // Number: the value
    // Table: (nm, value); Cauchy: (coefficient, unused); Sellmeier: (B, C in um^2).
    std::vector<std::array<double, 2>> rows;
    Material material = Material::Water;
    double temperatureC = 20.0;
};

// The draft of a quantity given as `model`, or as the number `value` when there is none (or a constant).
ModelDraft draftOf(const std::optional<SpectralFunction>& model, double value);
// A first draft of `form` for a quantity whose model is `model` and whose value at the scene wavelength is
// `value`: a table through the current values at 400, 550 and 700 nm; Cauchy with n unchanged at the scene
// wavelength (c0 = n - c1 / lambda^2, c1 = kFirstCauchyCoefficient); Sellmeier with N-BK7's coefficients;
// water at 20 C.
ModelDraft startDraft(ModelForm form, const std::optional<SpectralFunction>& model, double value,
                      double sceneWavelengthNm);
// The model the draft describes; none for Number (draft.number is then the value). Throws
// std::invalid_argument as the factories do.
std::optional<SpectralFunction> modelOf(const ModelDraft& draft, OpticalQuantity quantity);

// Cauchy's c1 a new model starts with, in um^2: about N-BK7's (0.0042), so the dispersion shows at once.
inline constexpr double kFirstCauchyCoefficient = 0.0042;

// A source's spectrum in the Fire panel: the scene's line (no spectrum of its own) or one of
// Spectrum::Kind.
enum class SpectrumForm { SceneLine, Lines, Uniform, Table, Blackbody, Sun };

// "scene line", "lines", "uniform", "table", "blackbody", "sun": the spectrum combo's choices.
std::span<const char* const> spectrumFormNames();

struct SpectrumDraft {
    SpectrumForm form = SpectrumForm::SceneLine;
    std::vector<std::array<double, 2>> rows;       // lines, table: (nm, weight)
    std::array<double, 2> boundsNm{400.0, 700.0};  // uniform, blackbody
    double kelvin = kSunKelvin;                    // blackbody
};

SpectrumDraft draftOf(const std::optional<Spectrum>& spectrum);
// A first draft of `form` for a source whose spectrum is `spectrum`: its wavelengths where they carry
// over (a range's bounds, a list's lines), else one line at the scene wavelength, 400-700 nm, a flat
// table over 400-700 nm, a blackbody at the sun's temperature over 380-780 nm.
SpectrumDraft startDraft(SpectrumForm form, const std::optional<Spectrum>& spectrum, double sceneWavelengthNm);
// The spectrum the draft describes; none for the scene line. Throws std::invalid_argument as the factories do.
std::optional<Spectrum> spectrumOf(const SpectrumDraft& draft);

}  // namespace dropscope::gui
