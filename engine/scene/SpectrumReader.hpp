#pragma once

#include "scene/JsonReader.hpp"
#include "spectrum/SpectralFunction.hpp"
#include "spectrum/Spectrum.hpp"

#include <variant>

namespace dropscope {

// A medium's n, kappa or sigma (docs/scene-format.md, "Media"): a number, or one of
// {"table_nm": [[lambda, value], ...]}, {"cauchy_um": [A, B, ...]}, {"sellmeier_um": {"B": [...], "C": [...]}},
// {"builtin": "water" | "bk7" | "fused_silica", "temperature_c": T}. Errors name the JSON path.
std::variant<double, SpectralFunction> readSpectralValue(const JsonReader& json, OpticalQuantity quantity);

// A source's "spectrum" (docs/scene-format.md, "Sources"): {"lines_nm": [[lambda, weight], ...]},
// {"uniform_nm": [lo, hi]}, {"table_nm": [[lambda, weight], ...]}, {"blackbody_K": T, "range_nm": [lo, hi]}
// or "sun".
Spectrum readSpectrum(const JsonReader& json);

}  // namespace dropscope
