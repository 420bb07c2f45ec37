#pragma once

#include "spectrum/SpectralFunction.hpp"

#include <optional>
#include <string>

namespace dropscope {

// An optical medium: complex refractive index n + i*kappa (seed chapter 3), or a real index n with an
// absorption coefficient sigma given directly. The numbers are the values at the scene wavelength; when
// the scene gives n, kappa or sigma as a function of wavelength (docs/scene-format.md, "Media"), the
// function is kept too, and photons of other wavelengths use mediumOpticsAt.
struct Medium {
    std::string name;
    double n = 1.0;
    std::optional<double> kappa;  // extinction coefficient, dimensionless
    std::optional<double> sigma;  // absorption coefficient as given, per scene unit
    // Intensity attenuation per scene unit: sigma, or 4*pi*kappa/lambda (seed eq. 3.13,
    // sigma = 2*omega*kappa/c with omega = 2*pi*c/lambda); 0 for a clear medium.
    double absorptionPerUnit = 0.0;
    // Dispersion: the functions of wavelength n, kappa and sigma were given as (absent: a number).
    std::optional<SpectralFunction> nModel = std::nullopt;
    std::optional<SpectralFunction> kappaModel = std::nullopt;
    std::optional<SpectralFunction> sigmaModel = std::nullopt;

    bool dispersive() const { return nModel || kappaModel || sigmaModel; }
};

// 4*pi*kappa/lambda, with lambda in the same length unit as the result's inverse.
double absorptionFromExtinction(double kappa, double wavelengthInSceneUnits);

// What a photon of one wavelength needs of a medium.
struct MediumOptics {
    double n = 1.0;
    double absorptionPerUnit = 0.0;  // per scene unit
};

// n and the absorption per scene unit at `wavelengthNm` (the models where given, else the numbers; a kappa
// always gives 4*pi*kappa/lambda at this wavelength). Throws what SpectralFunction::at throws.
MediumOptics mediumOpticsAt(const Medium& medium, double wavelengthNm, double unitInMetres);

// The absorption per scene unit of the medium's numbers: sigma, or 4*pi*kappa/lambda at `wavelengthNm`; 0 for a
// clear medium.
double absorptionPerUnitOf(const Medium& medium, double wavelengthNm, double unitInMetres);

// Sets n, kappa, sigma and absorptionPerUnit to their values at `wavelengthNm` from the models, and
// absorptionPerUnit from kappa or sigma. Throws what checkedSpectralValue throws.
void evaluateMediumAt(Medium& medium, double wavelengthNm, double unitInMetres);

// model.at(wavelengthNm), checked to be finite and > 0 for n, >= 0 for kappa and sigma: throws what
// SpectralFunction::at throws, and std::domain_error naming the value and the wavelength.
double checkedSpectralValue(const SpectralFunction& model, OpticalQuantity quantity, double wavelengthNm);

// "532 nm", "486.13 nm": a wavelength as messages print it.
std::string formatWavelength(double wavelengthNm);

// The wavelength, in the scene's unit, of `wavelengthNm`.
inline double wavelengthInUnits(double wavelengthNm, double unitInMetres) { return wavelengthNm * 1e-9 / unitInMetres; }

}  // namespace dropscope
