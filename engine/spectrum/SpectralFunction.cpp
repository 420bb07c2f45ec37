#include "spectrum/SpectralFunction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spectrum/Decimal.hpp"
#include "spectrum/EmbeddedData.hpp"
#include "spectrum/Water.hpp"

namespace dropscope {

namespace {

std::string range(const std::pair<double, double>& nm) {
    return shortestDecimal(nm.first) + "-" + shortestDecimal(nm.second) + " nm";
}

void requireFinite(double value, const std::string& what) {
    if (!std::isfinite(value))
        throw std::invalid_argument(what + " must be a finite number, not " + shortestDecimal(value));
}

// Published Sellmeier coefficients, docs/spectra.md "Built-in materials": B, C in um^2, validity in nm.
struct Glass {
    double b[3];
    double c[3];
    std::pair<double, double> domainNm;
};

// Schott N-BK7, SCHOTT optical glass catalogue (data sheet N-BK7), (S9).
constexpr Glass kBk7{{1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}, {300.0, 2500.0}};
// Fused silica, Malitson (1965), resonance wavelengths 0.0684043, 0.1162414, 9.896161 um squared, (S10).
constexpr Glass kFusedSilica{{0.6961663, 0.4079426, 0.8974794},
                             {0.0684043 * 0.0684043, 0.1162414 * 0.1162414, 9.896161 * 9.896161},
                             {210.0, 3710.0}};

const Glass& glass(Material material) { return material == Material::Bk7 ? kBk7 : kFusedSilica; }

// Sellmeier's n, docs/spectra.md (S3); domain_error where it has no real value.
double sellmeierIndex(const double* b, const double* cUm2, std::size_t terms, double wavelengthNm) {
    const double lambda2 = (wavelengthNm / 1000.0) * (wavelengthNm / 1000.0);
    double n2 = 1.0;
    for (std::size_t i = 0; i < terms; ++i) {
        const double denominator = lambda2 - cUm2[i];
        if (denominator == 0.0) {
            throw std::domain_error("the Sellmeier model has a pole at " + shortestDecimal(wavelengthNm) + " nm");
        }
        n2 += b[i] * lambda2 / denominator;
    }
    if (!(n2 > 0.0)) {
        throw std::domain_error("the Sellmeier model gives n^2 = " + shortestDecimal(n2) + " <= 0 at " +
                                shortestDecimal(wavelengthNm) + " nm");
    }
    return std::sqrt(n2);
}

// Hale and Querry's kappa of water (assets/data/water_kappa_hale_querry_1973.csv), parsed once.
const std::vector<std::pair<double, double>>& waterKappaTable() {
    static const std::vector<std::pair<double, double>> table = [] {
        std::vector<std::pair<double, double>> points;
        for (const auto& row : parseNumberTable(embedded::kWaterKappa, 2, "water_kappa_hale_querry_1973.csv")) {
            points.emplace_back(row[0], row[1]);
        }
        return points;
    }();
    return table;
}

// The segment [i-1, i] of ascending `points` that holds `x` (x within the first and last point).
std::size_t segmentOf(const std::vector<std::pair<double, double>>& points, double x) {
    const auto upper = std::lower_bound(points.begin() + 1, points.end() - 1, x,
                                        [](const std::pair<double, double>& p, double v) { return p.first < v; });
    return static_cast<std::size_t>(upper - points.begin());
}

// Piecewise linear, docs/spectra.md (S1).
double linear(const std::vector<std::pair<double, double>>& points, double x) {
    const std::size_t i = segmentOf(points, x);
    const auto& [x0, y0] = points[i - 1];
    const auto& [x1, y1] = points[i];
    const double s = (x - x0) / (x1 - x0);
    return y0 + s * (y1 - y0);
}

// Linear in the logarithm of the value (all values > 0), docs/spectra.md (S8).
double logLinear(const std::vector<std::pair<double, double>>& points, double x) {
    const std::size_t i = segmentOf(points, x);
    const auto& [x0, y0] = points[i - 1];
    const auto& [x1, y1] = points[i];
    const double s = (x - x0) / (x1 - x0);
    return y0 * std::pow(y1 / y0, s);
}

}  // namespace

std::string materialName(Material material) {
    switch (material) {
    case Material::Water: return "water";
    case Material::Bk7: return "bk7";
    case Material::FusedSilica: return "fused_silica";
    }
    throw std::invalid_argument("unknown material");
}

const char* opticalQuantityKey(OpticalQuantity quantity) {
    switch (quantity) {
    case OpticalQuantity::N: return "n";
    case OpticalQuantity::Kappa: return "kappa";
    case OpticalQuantity::Sigma: return "sigma";
    }
    return "?";
}

std::optional<Material> materialNamed(const std::string& name) {
    for (const Material material : {Material::Water, Material::Bk7, Material::FusedSilica}) {
        if (materialName(material) == name) return material;
    }
    return std::nullopt;
}

SpectralFunction SpectralFunction::constant(double value) {
    requireFinite(value, "a constant");
    SpectralFunction function;
    function.constant_ = value;
    return function;
}

SpectralFunction SpectralFunction::table(std::vector<std::pair<double, double>> pointsNm) {
    if (pointsNm.size() < 2) {
        throw std::invalid_argument("a table needs at least 2 points, not " + std::to_string(pointsNm.size()));
    }
    for (std::size_t i = 0; i < pointsNm.size(); ++i) {
        requireFinite(pointsNm[i].first, "a table wavelength");
        requireFinite(pointsNm[i].second, "a table value");
        if (pointsNm[i].first <= 0.0) {
            throw std::invalid_argument("table wavelengths must be > 0 nm, not " + shortestDecimal(pointsNm[i].first));
        }
        if (i > 0 && pointsNm[i].first <= pointsNm[i - 1].first) {
            throw std::invalid_argument("table wavelengths must be strictly ascending (" +
                                        shortestDecimal(pointsNm[i].first) + " nm after " +
                                        shortestDecimal(pointsNm[i - 1].first) + " nm)");
        }
    }
    SpectralFunction function;
    function.kind_ = Kind::Table;
    function.points_ = std::move(pointsNm);
    return function;
}

SpectralFunction SpectralFunction::cauchy(std::vector<double> coefficientsUm) {
    if (coefficientsUm.empty()) throw std::invalid_argument("a Cauchy model needs at least one coefficient");
    for (const double c : coefficientsUm) requireFinite(c, "a Cauchy coefficient");
    SpectralFunction function;
    function.kind_ = Kind::Cauchy;
    function.coefficients_ = std::move(coefficientsUm);
    return function;
}

SpectralFunction SpectralFunction::sellmeier(std::vector<double> b, std::vector<double> cUm2) {
    if (b.size() != cUm2.size()) {
        throw std::invalid_argument("Sellmeier B and C must have the same length (" + std::to_string(b.size()) +
                                    " and " + std::to_string(cUm2.size()) + ")");
    }
    if (b.empty()) throw std::invalid_argument("a Sellmeier model needs at least one term");
    for (const double value : b) requireFinite(value, "a Sellmeier B");
    for (const double value : cUm2) requireFinite(value, "a Sellmeier C");
    SpectralFunction function;
    function.kind_ = Kind::Sellmeier;
    function.coefficients_ = std::move(b);
    function.sellmeierC_ = std::move(cUm2);
    return function;
}

SpectralFunction SpectralFunction::builtin(Material material, OpticalQuantity quantity, double temperatureC) {
    const std::string name = materialName(material);
    if (quantity == OpticalQuantity::Sigma) throw std::invalid_argument("no built-in sigma for " + name);
    if (quantity == OpticalQuantity::Kappa && material != Material::Water) {
        throw std::invalid_argument("no built-in kappa for " + name);
    }
    requireFinite(temperatureC, "a temperature");
    const auto [lowC, highC] = kWaterTemperatureRangeC;
    if (material == Material::Water && quantity == OpticalQuantity::N &&
        !(temperatureC >= lowC && temperatureC <= highC)) {
        throw std::invalid_argument("the built-in water index is offered from " + shortestDecimal(lowC) + " to " +
                                    shortestDecimal(highC) + " degrees C, not " + shortestDecimal(temperatureC));
    }
    SpectralFunction function;
    function.kind_ = Kind::Builtin;
    function.material_ = material;
    function.quantity_ = quantity;
    function.temperatureC_ = temperatureC;
    return function;
}

std::optional<std::pair<double, double>> SpectralFunction::domainNm() const {
    switch (kind_) {
    case Kind::Constant:
    case Kind::Cauchy:
    case Kind::Sellmeier: return std::nullopt;
    case Kind::Table: return std::pair{points_.front().first, points_.back().first};
    case Kind::Builtin:
        if (material_ != Material::Water) return glass(material_).domainNm;
        if (quantity_ == OpticalQuantity::N) return kWaterIndexWavelengthRangeNm;
        return std::pair{waterKappaTable().front().first, waterKappaTable().back().first};
    }
    return std::nullopt;
}

double SpectralFunction::at(double wavelengthNm) const {
    const auto domain = domainNm();
    if (!std::isfinite(wavelengthNm) || wavelengthNm <= 0.0) {
        throw std::out_of_range(shortestDecimal(wavelengthNm) + " nm is not a wavelength (it must be > 0 nm)");
    }
    if (domain && (wavelengthNm < domain->first || wavelengthNm > domain->second)) {
        const std::string what = kind_ == Kind::Table ? std::string("the table")
                                                      : "the built-in " + materialName(material_) +
                                                            (quantity_ == OpticalQuantity::N ? " n" : " kappa");
        throw std::out_of_range(shortestDecimal(wavelengthNm) + " nm is outside " + what + " (" + range(*domain) + ")");
    }
    switch (kind_) {
    case Kind::Constant: return constant_;
    case Kind::Table: return linear(points_, wavelengthNm);
    case Kind::Cauchy: {
        // n = A + B/lambda^2 + C/lambda^4 + ..., lambda in um: docs/spectra.md (S2)
        const double inverseLambda2 = 1.0 / ((wavelengthNm / 1000.0) * (wavelengthNm / 1000.0));
        double value = 0.0;
        for (auto c = coefficients_.rbegin(); c != coefficients_.rend(); ++c) value = value * inverseLambda2 + *c;
        return value;
    }
    case Kind::Sellmeier:
        return sellmeierIndex(coefficients_.data(), sellmeierC_.data(), coefficients_.size(), wavelengthNm);
    case Kind::Builtin:
        if (material_ != Material::Water) {
            const Glass& g = glass(material_);
            return sellmeierIndex(g.b, g.c, 3, wavelengthNm);
        }
        if (quantity_ == OpticalQuantity::Kappa) return logLinear(waterKappaTable(), wavelengthNm);
        return iapwsWaterIndex(waterDensityAtOneBar(temperatureC_), temperatureC_ + 273.15, wavelengthNm);
    }
    return constant_;
}

}  // namespace dropscope
