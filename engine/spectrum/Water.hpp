#pragma once

#include <utility>

namespace dropscope {

// Liquid water's refractive index: the IAPWS formulation (Harvey, Gallagher and Levelt Sengers 1998;
// IAPWS R9-97), docs/spectra.md "Water".

// n of water of density `densityKgM3` at `temperatureK` and vacuum wavelength `wavelengthNm`, the release's
// equation as printed. Its stated range: -12 to 500 degrees C, 0 to 1060 kg/m^3, 200 to 1100 nm (within
// the narrower ranges it tabulates best).
double iapwsWaterIndex(double densityKgM3, double temperatureK, double wavelengthNm);

// The density of air-free liquid water at 0.1 MPa (docs/spectra.md names the formula and its source).
double waterDensityAtOneBar(double temperatureC);

// The temperatures (degrees C) and wavelengths (nm) where the built-in water index is offered.
inline constexpr std::pair<double, double> kWaterTemperatureRangeC{0.0, 100.0};
inline constexpr std::pair<double, double> kWaterIndexWavelengthRangeNm{200.0, 1100.0};

}  // namespace dropscope
