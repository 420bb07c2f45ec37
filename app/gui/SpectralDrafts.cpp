#include "gui/SpectralDrafts.hpp"

#include <algorithm>
#include <utility>

namespace dropscope::gui {

namespace {

constexpr std::array<ModelForm, 5> kNForms{ModelForm::Number, ModelForm::Table, ModelForm::Cauchy, ModelForm::Sellmeier,
                                           ModelForm::Builtin};
constexpr std::array<ModelForm, 3> kKappaForms{ModelForm::Number, ModelForm::Table, ModelForm::Builtin};
constexpr std::array<ModelForm, 2> kSigmaForms{ModelForm::Number, ModelForm::Table};
constexpr std::array<const char*, 6> kSpectrumForms{"scene line", "lines", "uniform", "table", "blackbody", "sun"};

// N-BK7 (docs/spectra.md (S9)): B and C in um^2, a first Sellmeier model that is a real glass.
constexpr std::array<std::array<double, 2>, 3> kBk7Terms{
    {{1.03961212, 0.00600069867}, {0.231792344, 0.0200179144}, {1.01046945, 103.560653}}};
// The wavelengths a first table samples the current model at.
constexpr std::array<double, 3> kTableStartNm{400.0, 550.0, 700.0};
constexpr std::array<double, 2> kVisibleNm{400.0, 700.0};

std::vector<std::array<double, 2>> rowsOf(const std::vector<std::pair<double, double>>& points) {
    std::vector<std::array<double, 2>> rows;
    for (const auto& [x, y] : points) rows.push_back({x, y});
    return rows;
}

std::vector<std::pair<double, double>> pointsOf(const std::vector<std::array<double, 2>>& rows) {
    std::vector<std::pair<double, double>> points;
    for (const auto& row : rows) points.emplace_back(row[0], row[1]);
    return points;
}

std::vector<double> column(const std::vector<std::array<double, 2>>& rows, std::size_t c) {
    std::vector<double> values;
    for (const auto& row : rows) values.push_back(row[c]);
    return values;
}

// The model's value at `nm`, or `fallback` where it has none (outside a table, a Sellmeier pole).
double valueOr(const std::optional<SpectralFunction>& model, double nm, double fallback) {
    if (!model) return fallback;
    try {
        return model->at(nm);
    } catch (const std::exception&) {
        return fallback;
    }
}

}  // namespace

std::span<const ModelForm> formsOf(OpticalQuantity quantity) {
    switch (quantity) {
    case OpticalQuantity::N: return kNForms;
    case OpticalQuantity::Kappa: return kKappaForms;
    case OpticalQuantity::Sigma: return kSigmaForms;
    }
    return kSigmaForms;
}

const char* formName(ModelForm form) {
    switch (form) {
    case ModelForm::Number: return "number";
    case ModelForm::Table: return "table";
    case ModelForm::Cauchy: return "Cauchy";
    case ModelForm::Sellmeier: return "Sellmeier";
    case ModelForm::Builtin: return "builtin";
    }
    return "?";
}

ModelDraft draftOf(const std::optional<SpectralFunction>& model, double value) {
    ModelDraft draft;
    draft.number = value;
    if (!model) return draft;
    switch (model->kind()) {
    case SpectralFunction::Kind::Constant: break;  // a number, as the medium's value shows it
    case SpectralFunction::Kind::Table:
        draft.form = ModelForm::Table;
        draft.rows = rowsOf(model->tablePointsNm());
        break;
    case SpectralFunction::Kind::Cauchy:
        draft.form = ModelForm::Cauchy;
        for (const double c : model->coefficients()) draft.rows.push_back({c, 0.0});
        break;
    case SpectralFunction::Kind::Sellmeier:
        draft.form = ModelForm::Sellmeier;
        for (std::size_t i = 0; i < model->coefficients().size(); ++i) {
            draft.rows.push_back({model->coefficients()[i], model->sellmeierC()[i]});
        }
        break;
    case SpectralFunction::Kind::Builtin:
        draft.form = ModelForm::Builtin;
        draft.material = model->material();
        draft.temperatureC = model->temperatureC();
        break;
    }
    return draft;
}

ModelDraft startDraft(ModelForm form, const std::optional<SpectralFunction>& model, double value,
                      double sceneWavelengthNm) {
    ModelDraft draft;
    draft.form = form;
    draft.number = value;
    switch (form) {
    case ModelForm::Number: break;
    case ModelForm::Table:
        for (const double nm : kTableStartNm) draft.rows.push_back({nm, valueOr(model, nm, value)});
        break;
    case ModelForm::Cauchy: {
        const double lambdaUm = sceneWavelengthNm * 1e-3;
        draft.rows = {{value - kFirstCauchyCoefficient / (lambdaUm * lambdaUm), 0.0}, {kFirstCauchyCoefficient, 0.0}};
        break;
    }
    case ModelForm::Sellmeier: draft.rows.assign(kBk7Terms.begin(), kBk7Terms.end()); break;
    case ModelForm::Builtin: break;  // water at 20 C
    }
    return draft;
}

std::optional<SpectralFunction> modelOf(const ModelDraft& draft, OpticalQuantity quantity) {
    switch (draft.form) {
    case ModelForm::Number: return std::nullopt;
    case ModelForm::Table: return SpectralFunction::table(pointsOf(draft.rows));
    case ModelForm::Cauchy: return SpectralFunction::cauchy(column(draft.rows, 0));
    case ModelForm::Sellmeier: return SpectralFunction::sellmeier(column(draft.rows, 0), column(draft.rows, 1));
    case ModelForm::Builtin: return SpectralFunction::builtin(draft.material, quantity, draft.temperatureC);
    }
    return std::nullopt;
}

std::span<const char* const> spectrumFormNames() { return kSpectrumForms; }

SpectrumDraft draftOf(const std::optional<Spectrum>& spectrum) {
    SpectrumDraft draft;
    if (!spectrum) return draft;
    draft.form = static_cast<SpectrumForm>(static_cast<int>(spectrum->kind()) + 1);  // Spectrum::Kind's order
    draft.rows = rowsOf(spectrum->pointsNm());
    if (spectrum->kind() == Spectrum::Kind::Uniform || spectrum->kind() == Spectrum::Kind::Blackbody) {
        draft.boundsNm = {spectrum->boundsNm().first, spectrum->boundsNm().second};
    }
    if (spectrum->kind() == Spectrum::Kind::Blackbody) draft.kelvin = spectrum->kelvin();
    return draft;
}

SpectrumDraft startDraft(SpectrumForm form, const std::optional<Spectrum>& spectrum, double sceneWavelengthNm) {
    SpectrumDraft draft = draftOf(spectrum);
    const auto [lo, hi] = spectrum ? spectrum->rangeNm() : std::pair{sceneWavelengthNm, sceneWavelengthNm};
    const bool hasRange = lo < hi;
    draft.form = form;
    switch (form) {
    case SpectrumForm::SceneLine:
    case SpectrumForm::Sun: break;
    case SpectrumForm::Lines:
        if (!spectrum || spectrum->kind() != Spectrum::Kind::Lines) draft.rows = {{sceneWavelengthNm, 1.0}};
        break;
    case SpectrumForm::Uniform: draft.boundsNm = hasRange ? std::array{lo, hi} : kVisibleNm; break;
    case SpectrumForm::Table: {
        const auto [from, to] = hasRange ? std::pair{lo, hi} : std::pair{kVisibleNm[0], kVisibleNm[1]};
        draft.rows = {{from, 1.0}, {to, 1.0}};
        break;
    }
    case SpectrumForm::Blackbody:
        draft.kelvin = kSunKelvin;
        draft.boundsNm = {kSunRangeNm.first, kSunRangeNm.second};
        break;
    }
    return draft;
}

std::optional<Spectrum> spectrumOf(const SpectrumDraft& draft) {
    switch (draft.form) {
    case SpectrumForm::SceneLine: return std::nullopt;
    case SpectrumForm::Lines: return Spectrum::lines(pointsOf(draft.rows));
    case SpectrumForm::Uniform: return Spectrum::uniform(draft.boundsNm[0], draft.boundsNm[1]);
    case SpectrumForm::Table: return Spectrum::table(pointsOf(draft.rows));
    case SpectrumForm::Blackbody: return Spectrum::blackbody(draft.kelvin, draft.boundsNm[0], draft.boundsNm[1]);
    case SpectrumForm::Sun: return Spectrum::sun();
    }
    return std::nullopt;
}

}  // namespace dropscope::gui
