#include "scene/Medium.hpp"

#include "spectrum/Decimal.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace dropscope {

double absorptionFromExtinction(double kappa, double wavelengthInSceneUnits) {
    return 4.0 * std::numbers::pi * kappa / wavelengthInSceneUnits;  // seed eq. 3.13
}

std::string formatWavelength(double wavelengthNm) { return shortestDecimal(wavelengthNm) + " nm"; }

namespace {

// sigma, or 4 pi kappa / lambda at `wavelengthNm` (seed eq. 3.13); 0 for a clear medium.
double absorptionOf(const std::optional<double>& sigma, const std::optional<double>& kappa, double wavelengthNm,
                    double unitInMetres) {
    if (sigma) return *sigma;
    if (kappa) return absorptionFromExtinction(*kappa, wavelengthInUnits(wavelengthNm, unitInMetres));
    return 0.0;
}

// A model's value, or the number when there is none.
std::optional<double> valueAt(const std::optional<SpectralFunction>& model, const std::optional<double>& number,
                              double wavelengthNm) {
    if (model && number) return model->at(wavelengthNm);
    return number;
}

}  // namespace

double checkedSpectralValue(const SpectralFunction& model, OpticalQuantity quantity, double wavelengthNm) {
    const double value = model.at(wavelengthNm);
    const bool positive = quantity == OpticalQuantity::N;
    if (!std::isfinite(value) || (positive ? value <= 0.0 : value < 0.0)) {
        std::ostringstream message;
        message << opticalQuantityKey(quantity) << " is " << value << " at " << formatWavelength(wavelengthNm)
                << (positive ? " (must be > 0)" : " (must be >= 0)");
        throw std::domain_error(message.str());
    }
    return value;
}

MediumOptics mediumOpticsAt(const Medium& medium, double wavelengthNm, double unitInMetres) {
    MediumOptics optics;
    optics.n = medium.nModel ? medium.nModel->at(wavelengthNm) : medium.n;
    optics.absorptionPerUnit =
        absorptionOf(valueAt(medium.sigmaModel, medium.sigma, wavelengthNm),
                     valueAt(medium.kappaModel, medium.kappa, wavelengthNm), wavelengthNm, unitInMetres);
    return optics;
}

double absorptionPerUnitOf(const Medium& medium, double wavelengthNm, double unitInMetres) {
    return absorptionOf(medium.sigma, medium.kappa, wavelengthNm, unitInMetres);
}

void evaluateMediumAt(Medium& medium, double wavelengthNm, double unitInMetres) {
    if (medium.nModel) medium.n = checkedSpectralValue(*medium.nModel, OpticalQuantity::N, wavelengthNm);
    if (medium.kappaModel)
        medium.kappa = checkedSpectralValue(*medium.kappaModel, OpticalQuantity::Kappa, wavelengthNm);
    if (medium.sigmaModel)
        medium.sigma = checkedSpectralValue(*medium.sigmaModel, OpticalQuantity::Sigma, wavelengthNm);
    medium.absorptionPerUnit = absorptionPerUnitOf(medium, wavelengthNm, unitInMetres);
}

}  // namespace dropscope
