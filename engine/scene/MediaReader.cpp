#include "scene/MediaReader.hpp"

#include "scene/JsonPath.hpp"

namespace dropscope {

namespace {

Medium readMedium(const std::string& name, const JsonReader& json, double wavelengthInSceneUnits) {
    json.expectKeys({"n", "kappa", "sigma"});
    Medium medium;
    medium.name = name;
    medium.n = json.member("n").positive();
    if (const auto kappa = json.optionalMember("kappa")) medium.kappa = kappa->nonNegative();
    if (const auto sigma = json.optionalMember("sigma")) {
        if (medium.kappa) sigma->fail("give either \"kappa\" or \"sigma\", not both");
        medium.sigma = sigma->nonNegative();
    }
    if (medium.sigma) {
        medium.absorptionPerUnit = *medium.sigma;
    } else if (medium.kappa) {
        medium.absorptionPerUnit = absorptionFromExtinction(*medium.kappa, wavelengthInSceneUnits);
    }
    return medium;
}

}  // namespace

std::vector<Medium> readMedia(const JsonReader& json, double wavelengthInSceneUnits) {
    std::vector<Medium> media;
    for (const auto& [name, value] : json.members()) {
        if (name.empty()) value.fail("a medium name must not be empty");
        media.push_back(readMedium(name, value, wavelengthInSceneUnits));
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
