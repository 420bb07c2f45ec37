#include "spectrum/Water.hpp"

#include <cmath>

namespace dropscope {

namespace {

// IAPWS R9-97 (Harvey, Gallagher and Levelt Sengers 1998), its reference constants and coefficients as
// published: docs/spectra.md (S5).
constexpr double kReferenceTemperatureK = 273.15;
constexpr double kReferenceDensityKgM3 = 1000.0;
constexpr double kReferenceWavelengthUm = 0.589;
constexpr double kUltravioletResonance = 0.229202;  // lambda_UV, reduced (lambda / lambda*)
constexpr double kInfraredResonance = 5.432937;     // lambda_IR, reduced
constexpr double kA[8] = {0.244257733,    0.974634476e-2, -0.373234996e-2, 0.268678472e-3,
                          0.158920570e-2, 0.245934259e-2, 0.900704920,     -0.166626219e-1};

// Temperatures on the IPTS-68 scale, which Kell's fit uses, against ITS-90 (ours), 0-100 C.
constexpr double kIpts68PerIts90 = 1.00024;

}  // namespace

double iapwsWaterIndex(double densityKgM3, double temperatureK, double wavelengthNm) {
    const double rho = densityKgM3 / kReferenceDensityKgM3;
    const double theta = temperatureK / kReferenceTemperatureK;
    const double lambda = wavelengthNm / 1000.0 / kReferenceWavelengthUm;
    const double lambda2 = lambda * lambda;
    // The Lorentz-Lorenz function (n^2 - 1)/(n^2 + 2), docs/spectra.md (S5)
    const double lorentzLorenz =
        rho * (kA[0] + kA[1] * rho + kA[2] * theta + kA[3] * lambda2 * theta + kA[4] / lambda2 +
               kA[5] / (lambda2 - kUltravioletResonance * kUltravioletResonance) +
               kA[6] / (lambda2 - kInfraredResonance * kInfraredResonance) + kA[7] * rho * rho);
    // Solved for n, docs/spectra.md (S6)
    return std::sqrt((1.0 + 2.0 * lorentzLorenz) / (1.0 - lorentzLorenz));
}

double waterDensityAtOneBar(double temperatureC) {
    // Kell's t is on the IPTS-68 scale: t68 = 1.00024 t90 (Saunders 1990), docs/spectra.md (S7)
    const double t = kIpts68PerIts90 * temperatureC;
    // Kell (1975), air-free water at 1 atm: docs/spectra.md (S7)
    const double numerator =
        999.83952 +
        t * (16.945176 + t * (-7.9870401e-3 + t * (-46.170461e-6 + t * (105.56302e-9 + t * -280.54235e-12))));
    return numerator / (1.0 + 16.879850e-3 * t);
}

}  // namespace dropscope
