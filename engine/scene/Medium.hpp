#pragma once

#include <optional>
#include <string>

namespace dropscope {

// An optical medium at the scene wavelength: complex refractive index n + i*kappa (seed chapter 3),
// or a real index n with an absorption coefficient sigma given directly.
struct Medium {
    std::string name;
    double n = 1.0;
    std::optional<double> kappa;  // extinction coefficient, dimensionless
    std::optional<double> sigma;  // absorption coefficient as given, per scene unit
    // Intensity attenuation per scene unit: sigma, or 4*pi*kappa/lambda (seed eq. 3.13,
    // sigma = 2*omega*kappa/c with omega = 2*pi*c/lambda); 0 for a clear medium.
    double absorptionPerUnit = 0.0;
};

// 4*pi*kappa/lambda, with lambda in the same length unit as the result's inverse.
double absorptionFromExtinction(double kappa, double wavelengthInSceneUnits);

}  // namespace dropscope
