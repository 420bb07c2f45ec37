#include "scene/SourceReader.hpp"

#include "scene/JsonPath.hpp"
#include "scene/SpectrumReader.hpp"

namespace dropscope {

namespace {

constexpr const char* kPolarisationForms =
    R"("unpolarised", {"linear_deg": A, "reference": [x, y, z]} or {"stokes": [I, Q, U, V], "reference": [x, y, z]})";

StokesVector readStokes(const JsonReader& json) {
    const std::vector<JsonReader> elements = json.elements();
    if (elements.size() != 4) json.fail("must be [I, Q, U, V], four numbers");
    StokesVector stokes;
    for (Eigen::Index k = 0; k < 4; ++k) stokes[k] = elements[static_cast<std::size_t>(k)].number();
    json.construct([&] { checkPolarisationStokes(stokes); });
    return stokes;
}

SourcePolarisation readPolarisation(const JsonReader& json, const Source& source) {
    if (json.isString()) {
        const std::string text = json.string();
        if (text != "unpolarised")
            json.fail("unknown polarisation " + jsonpath::quoted(text) + " (known: " + kPolarisationForms + ")");
        return {};
    }
    json.expectObject();
    if (source.type == SourceType::PointSource) json.fail("a point source is unpolarised only");
    SourcePolarisation polarisation;
    if (const auto angle = json.optionalMember("linear_deg")) {
        json.expectKeys({"linear_deg", "reference"});
        polarisation.kind = PolarisationKind::Linear;
        polarisation.linearDeg = angle->number();
    } else if (const auto stokes = json.optionalMember("stokes")) {
        json.expectKeys({"stokes", "reference"});
        polarisation.kind = PolarisationKind::Stokes;
        polarisation.stokes = readStokes(*stokes);
    } else {
        json.fail(std::string("expected one of ") + kPolarisationForms);
    }
    const JsonReader reference = json.member("reference");
    polarisation.reference = reference.vector3();
    reference.construct([&] { checkPolarisationReference(polarisation.reference, source.direction); });
    return polarisation;
}

}  // namespace

Source readSource(const JsonReader& json) {
    const JsonReader typeJson = json.member("type");
    const std::string type = typeJson.string();
    Source source;
    if (type == "beam") {
        json.expectKeys({"type", "origin", "direction", "radius", "polarisation", "spectrum", "divergence_deg"});
        source.type = SourceType::Beam;
    } else if (type == "ray") {
        json.expectKeys({"type", "origin", "direction", "polarisation", "spectrum", "divergence_deg"});
        source.type = SourceType::Ray;
    } else if (type == "point") {
        json.expectKeys({"type", "origin", "polarisation", "spectrum"});
        source.type = SourceType::PointSource;
    } else {
        typeJson.fail("unknown source type " + jsonpath::quoted(type) + " (known: beam, ray, point)");
    }
    source.origin = json.member("origin").vector3();
    if (source.type != SourceType::PointSource) source.direction = json.member("direction").direction();
    if (source.type == SourceType::Beam) source.radius = json.member("radius").positive();
    if (const auto polarisation = json.optionalMember("polarisation")) {
        source.polarisation = readPolarisation(*polarisation, source);
    }
    if (const auto spectrum = json.optionalMember("spectrum")) source.spectrum = readSpectrum(*spectrum);
    if (const auto divergence = json.optionalMember("divergence_deg")) {
        source.divergenceDeg = divergence->nonNegative();
        divergence->construct([&] { checkDivergence(source); });
    }
    return source;
}

}  // namespace dropscope
