#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dropscope {

// A material's built-in optical data (docs/spectra.md, "Built-in materials").
enum class Material { Water, Bk7, FusedSilica };

// "water", "bk7", "fused_silica": as scene files name them.
std::string materialName(Material material);
std::optional<Material> materialNamed(const std::string& name);

// Which of a medium's quantities a function gives: the real index n, the extinction coefficient kappa
// (dimensionless), or the absorption coefficient sigma (per scene unit).
enum class OpticalQuantity { N, Kappa, Sigma };

// "n", "kappa", "sigma": the medium's keys in a scene file.
const char* opticalQuantityKey(OpticalQuantity quantity);

// A real function of the vacuum wavelength (in nm): a medium's n, kappa or sigma as the scene gives it
// (docs/scene-format.md, "Media"). A value type; cheap to copy except for tables.
//   constant     the number itself, at every wavelength;
//   table        piecewise linear through (lambda, value) points, lambda strictly ascending, >= 2 points,
//                defined on [first lambda, last lambda] only;
//   cauchy       n = A + B/lambda^2 + C/lambda^4 + ..., lambda in micrometres, >= 1 coefficient;
//   sellmeier    n^2 = 1 + sum_i B_i lambda^2 / (lambda^2 - C_i), lambda in micrometres, C_i in um^2;
//   builtin      a Material's n (water: IAPWS R9-97 at `temperatureC` and 0.1 MPa; bk7, fused_silica:
//                their published Sellmeier coefficients) or kappa (water: the table of
//                assets/data/water_kappa_hale_querry_1973.csv), each on its source's validity range.
class SpectralFunction {
public:
    enum class Kind { Constant, Table, Cauchy, Sellmeier, Builtin };

    // A constant, the default (1).
    SpectralFunction() = default;
    static SpectralFunction constant(double value);
    // Each of these throws std::invalid_argument naming what is wrong (not where: the caller knows) for
    // points not strictly ascending, fewer than 2 points, non-finite numbers, no coefficients, B and C of
    // different lengths, ...
    static SpectralFunction table(std::vector<std::pair<double, double>> pointsNm);
    static SpectralFunction cauchy(std::vector<double> coefficientsUm);
    static SpectralFunction sellmeier(std::vector<double> b, std::vector<double> cUm2);
    // Throws std::invalid_argument when the material has no data for the quantity (bk7's kappa, any
    // sigma) or a temperature outside the material's validity range (water: kWaterTemperatureRangeC).
    static SpectralFunction builtin(Material material, OpticalQuantity quantity, double temperatureC = 20.0);

    Kind kind() const { return kind_; }
    bool isConstant() const { return kind_ == Kind::Constant; }

    // The value at `wavelengthNm`. Throws std::out_of_range, with a message that names the wavelength and
    // the valid range ("700 nm is outside the table (400-650 nm)"), outside domainNm(); std::domain_error
    // where a model has no real value (a Sellmeier pole, n^2 <= 0).
    double at(double wavelengthNm) const;
    // The wavelengths where at() is defined, both ends included; nullopt: every wavelength > 0.
    std::optional<std::pair<double, double>> domainNm() const;

    // What the scene file gave, for writing it back.
    double constantValue() const { return constant_; }
    const std::vector<std::pair<double, double>>& tablePointsNm() const { return points_; }
    const std::vector<double>& coefficients() const { return coefficients_; }  // Cauchy, Sellmeier B
    const std::vector<double>& sellmeierC() const { return sellmeierC_; }
    Material material() const { return material_; }
    OpticalQuantity quantity() const { return quantity_; }
    double temperatureC() const { return temperatureC_; }

    friend bool operator==(const SpectralFunction&, const SpectralFunction&) = default;

private:
    Kind kind_ = Kind::Constant;
    double constant_ = 1.0;
    std::vector<std::pair<double, double>> points_;
    std::vector<double> coefficients_;
    std::vector<double> sellmeierC_;
    Material material_ = Material::Water;
    OpticalQuantity quantity_ = OpticalQuantity::N;
    double temperatureC_ = 20.0;
};

}  // namespace dropscope
