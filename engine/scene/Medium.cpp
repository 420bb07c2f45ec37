#include "scene/Medium.hpp"

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace dropscope {

double absorptionFromExtinction(double kappa, double wavelengthInSceneUnits) {
    return 4.0 * std::numbers::pi * kappa / wavelengthInSceneUnits;  // seed eq. 3.13
}

std::string formatWavelength(double wavelengthNm) {
    std::ostringstream text;
    text << std::setprecision(10) << wavelengthNm << " nm";
    return text.str();
}

double checkedSpectralValue(const SpectralFunction& model, OpticalQuantity quantity, double wavelengthNm) {
    const double value = model.at(wavelengthNm);
    const bool positive = quantity == OpticalQuantity::N;
    if (!std::isfinite(value) || (positive ? value <= 0.0 : value < 0.0)) {
        std::ostringstream message;
        message << (quantity == OpticalQuantity::N       ? "n"
                    : quantity == OpticalQuantity::Kappa ? "kappa"
                                                         : "sigma")
                << " is " << value << " at " << formatWavelength(wavelengthNm)
                << (positive ? " (must be > 0)" : " (must be >= 0)");
        throw std::domain_error(message.str());
    }
    return value;
}

MediumOptics mediumOpticsAt(const Medium& medium, double wavelengthNm, double unitInMetres) {
    MediumOptics optics;
    optics.n = medium.nModel ? medium.nModel->at(wavelengthNm) : medium.n;
    if (medium.sigma) {
        optics.absorptionPerUnit = medium.sigmaModel ? medium.sigmaModel->at(wavelengthNm) : *medium.sigma;
    } else if (medium.kappa) {
        const double kappa = medium.kappaModel ? medium.kappaModel->at(wavelengthNm) : *medium.kappa;
        optics.absorptionPerUnit = absorptionFromExtinction(kappa, wavelengthInUnits(wavelengthNm, unitInMetres));
    }
    return optics;
}

void evaluateMediumAt(Medium& medium, double wavelengthNm, double unitInMetres) {
    if (medium.nModel) medium.n = checkedSpectralValue(*medium.nModel, OpticalQuantity::N, wavelengthNm);
    if (medium.kappaModel)
        medium.kappa = checkedSpectralValue(*medium.kappaModel, OpticalQuantity::Kappa, wavelengthNm);
    if (medium.sigmaModel)
        medium.sigma = checkedSpectralValue(*medium.sigmaModel, OpticalQuantity::Sigma, wavelengthNm);
    medium.absorptionPerUnit = 0.0;
    if (medium.sigma) {
        medium.absorptionPerUnit = *medium.sigma;
    } else if (medium.kappa) {
        medium.absorptionPerUnit =
            absorptionFromExtinction(*medium.kappa, wavelengthInUnits(wavelengthNm, unitInMetres));
    }
}

}  // namespace dropscope
