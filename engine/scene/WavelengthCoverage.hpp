#pragma once

#include "scene/Medium.hpp"
#include "scene/Source.hpp"

#include <optional>
#include <string>
#include <vector>

namespace dropscope {

// A medium whose n, kappa or sigma cannot be evaluated at a wavelength some source emits.
struct WavelengthCoverageProblem {
    std::size_t medium = 0;
    OpticalQuantity quantity = OpticalQuantity::N;
    std::size_t source = 0;
    std::string message;  // what SpectralFunction::at or checkedSpectralValue said
};

// The first medium model (in medium order: n, kappa, sigma) that fails at a wavelength of a source's spectrum
// (sourceSpectrum with the scene wavelength): every line of a line spectrum is evaluated; a continuous spectrum
// must lie within the model's domain, and the model is evaluated at its ends and at
// kCoverageSamplesPerSpectrum wavelengths between them (docs/spectra.md, "Checking media against spectra").
std::optional<WavelengthCoverageProblem> findWavelengthCoverageProblem(const std::vector<Medium>& media,
                                                                       const std::vector<Source>& sources,
                                                                       double sceneWavelengthNm);

// How densely a continuous spectrum's range is checked: finer than any tabulated medium data in assets/data
// (1 nm over 360-830 nm needs ~470), coarse enough to cost nothing at load.
inline constexpr int kCoverageSamplesPerSpectrum = 2048;

}  // namespace dropscope
