#include "scene/SpectrumReader.hpp"

#include "scene/JsonPath.hpp"

#include <stdexcept>

namespace dropscope {

namespace {

constexpr const char* kValueForms =
    R"(a number, {"table_nm": [[lambda, value], ...]}, {"cauchy_um": [A, B, ...]}, )"
    R"({"sellmeier_um": {"B": [...], "C": [...]}} or {"builtin": "water" | "bk7" | "fused_silica"})";
constexpr const char* kSpectrumForms =
    R"({"lines_nm": [[lambda, weight], ...]}, {"uniform_nm": [lo, hi]}, {"table_nm": [[lambda, weight], ...]}, )"
    R"({"blackbody_K": T, "range_nm": [lo, hi]} or "sun")";

// Runs `make`, turning the models' exceptions into a scene error at `json`'s path.
template <class Make>
auto atPath(const JsonReader& json, Make make) -> decltype(make()) {
    try {
        return make();
    } catch (const std::logic_error& error) {  // invalid_argument, out_of_range, domain_error
        json.fail(error.what());
    }
}

std::vector<std::pair<double, double>> readPairs(const JsonReader& json, const char* second) {
    std::vector<std::pair<double, double>> pairs;
    for (const JsonReader& element : json.elements()) {
        const std::vector<JsonReader> pair = element.fixedArray(2, std::string("[lambda, ") + second + "]");
        pairs.emplace_back(pair[0].positive(), pair[1].number());
    }
    return pairs;
}

std::vector<double> readNumbers(const JsonReader& json) {
    std::vector<double> numbers;
    for (const JsonReader& element : json.elements()) numbers.push_back(element.number());
    return numbers;
}

}  // namespace

std::variant<double, SpectralFunction> readSpectralValue(const JsonReader& json, OpticalQuantity quantity) {
    if (json.isNumber()) return quantity == OpticalQuantity::N ? json.positive() : json.nonNegative();
    if (!json.isObject()) json.fail(std::string("expected ") + kValueForms);
    if (const auto table = json.optionalMember("table_nm")) {
        json.expectKeys({"table_nm"});
        const auto points = readPairs(*table, "value");
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double value = points[i].second;
            if (quantity == OpticalQuantity::N ? value <= 0.0 : value < 0.0) {
                table->fail("value " + std::to_string(value) + " at " + std::to_string(points[i].first) +
                            " nm must be " + (quantity == OpticalQuantity::N ? "> 0" : ">= 0"));
            }
        }
        return atPath(*table, [&] { return SpectralFunction::table(points); });
    }
    if (const auto cauchy = json.optionalMember("cauchy_um")) {
        json.expectKeys({"cauchy_um"});
        if (quantity != OpticalQuantity::N) cauchy->fail("Cauchy's formula gives a refractive index: use it for n");
        return atPath(*cauchy, [&] { return SpectralFunction::cauchy(readNumbers(*cauchy)); });
    }
    if (const auto sellmeier = json.optionalMember("sellmeier_um")) {
        json.expectKeys({"sellmeier_um"});
        if (quantity != OpticalQuantity::N)
            sellmeier->fail("Sellmeier's formula gives a refractive index: use it for n");
        sellmeier->expectKeys({"B", "C"});
        const std::vector<double> b = readNumbers(sellmeier->member("B"));
        const std::vector<double> c = readNumbers(sellmeier->member("C"));
        return atPath(*sellmeier, [&] { return SpectralFunction::sellmeier(b, c); });
    }
    if (const auto builtin = json.optionalMember("builtin")) {
        json.expectKeys({"builtin", "temperature_c"});
        const std::string name = builtin->string();
        const std::optional<Material> material = materialNamed(name);
        if (!material)
            builtin->fail("unknown material " + jsonpath::quoted(name) + " (known: water, bk7, fused_silica)");
        double temperature = 20.0;
        if (const auto t = json.optionalMember("temperature_c")) {
            if (*material != Material::Water) t->fail("only water's index depends on a temperature here");
            temperature = t->number();
            return atPath(*t, [&] { return SpectralFunction::builtin(*material, quantity, temperature); });
        }
        return atPath(*builtin, [&] { return SpectralFunction::builtin(*material, quantity, temperature); });
    }
    json.fail(std::string("expected ") + kValueForms);
}

Spectrum readSpectrum(const JsonReader& json) {
    if (json.isString()) {
        const std::string name = json.string();
        if (name != "sun")
            json.fail("unknown spectrum " + jsonpath::quoted(name) + " (expected " + kSpectrumForms + ")");
        return Spectrum::sun();
    }
    if (!json.isObject()) json.fail(std::string("expected ") + kSpectrumForms);
    if (const auto lines = json.optionalMember("lines_nm")) {
        json.expectKeys({"lines_nm"});
        const auto points = readPairs(*lines, "weight");
        return atPath(*lines, [&] { return Spectrum::lines(points); });
    }
    if (const auto uniform = json.optionalMember("uniform_nm")) {
        json.expectKeys({"uniform_nm"});
        const std::vector<JsonReader> bounds = uniform->fixedArray(2, "[lo, hi]");
        const double lo = bounds[0].positive();
        const double hi = bounds[1].positive();
        return atPath(*uniform, [&] { return Spectrum::uniform(lo, hi); });
    }
    if (const auto table = json.optionalMember("table_nm")) {
        json.expectKeys({"table_nm"});
        const auto points = readPairs(*table, "weight");
        return atPath(*table, [&] { return Spectrum::table(points); });
    }
    if (const auto kelvin = json.optionalMember("blackbody_K")) {
        json.expectKeys({"blackbody_K", "range_nm"});
        const double temperature = kelvin->positive();
        const JsonReader range = json.member("range_nm");
        const std::vector<JsonReader> bounds = range.fixedArray(2, "[lo, hi]");
        const double lo = bounds[0].positive();
        const double hi = bounds[1].positive();
        return atPath(range, [&] { return Spectrum::blackbody(temperature, lo, hi); });
    }
    json.fail(std::string("expected ") + kSpectrumForms);
}

}  // namespace dropscope
