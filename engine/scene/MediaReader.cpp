#include "scene/MediaReader.hpp"

#include "scene/JsonPath.hpp"
#include "scene/SpectrumReader.hpp"

#include <stdexcept>

namespace dropscope {

namespace {

// Reads one of n, kappa, sigma: its number, or its model and the model's value at the scene wavelength.
void readQuantity(const JsonReader& json, OpticalQuantity quantity, double wavelengthNm, double& number,
                  std::optional<SpectralFunction>& model) {
    auto value = readSpectralValue(json, quantity);
    if (auto* constant = std::get_if<double>(&value)) {
        number = *constant;
        return;
    }
    model = std::get<SpectralFunction>(std::move(value));
    try {
        number = checkedSpectralValue(*model, quantity, wavelengthNm);
    } catch (const std::logic_error& error) {
        json.fail(std::string(error.what()) + " (the scene's \"wavelength_nm\")");
    }
}

Medium readMedium(const std::string& name, const JsonReader& json, double wavelengthNm, double unitInMetres) {
    json.expectKeys({"n", "kappa", "sigma"});
    Medium medium;
    medium.name = name;
    readQuantity(json.member("n"), OpticalQuantity::N, wavelengthNm, medium.n, medium.nModel);
    if (const auto kappa = json.optionalMember("kappa")) {
        medium.kappa = 0.0;
        readQuantity(*kappa, OpticalQuantity::Kappa, wavelengthNm, *medium.kappa, medium.kappaModel);
    }
    if (const auto sigma = json.optionalMember("sigma")) {
        if (medium.kappa) sigma->fail("give either \"kappa\" or \"sigma\", not both");
        medium.sigma = 0.0;
        readQuantity(*sigma, OpticalQuantity::Sigma, wavelengthNm, *medium.sigma, medium.sigmaModel);
    }
    medium.absorptionPerUnit = absorptionPerUnitOf(medium, wavelengthNm, unitInMetres);
    return medium;
}

}  // namespace

std::vector<Medium> readMedia(const JsonReader& json, double wavelengthNm, double unitInMetres) {
    std::vector<Medium> media;
    for (const auto& [name, value] : json.members()) {
        if (name.empty()) value.fail("a medium name must not be empty");
        media.push_back(readMedium(name, value, wavelengthNm, unitInMetres));
    }
    return media;
}

MediumId readMediumName(const JsonReader& json, const std::vector<Medium>& media) {
    const std::string name = json.string();
    std::string defined;
    for (std::size_t id = 0; id < media.size(); ++id) {
        if (media[id].name == name) return static_cast<MediumId>(id);
        defined += (id == 0 ? "" : ", ") + media[id].name;
    }
    json.fail("unknown medium " + jsonpath::quoted(name) +
              (media.empty() ? " (no media are defined)" : " (defined: " + defined + ")"));
}

}  // namespace dropscope
