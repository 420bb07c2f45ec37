#pragma once

#include "geometry/Shape.hpp"
#include "scene/JsonReader.hpp"
#include "scene/Medium.hpp"

#include <vector>

namespace dropscope {

// The "media" object: {name: {"n": ..., "kappa" | "sigma": ...}}, in file order; each of n, kappa, sigma a
// number or a function of wavelength (scene/SpectrumReader.hpp). The numbers are evaluated at the scene
// wavelength, and absorption per scene unit is computed from kappa with that wavelength in the scene unit.
std::vector<Medium> readMedia(const JsonReader& json, double wavelengthNm, double unitInMetres);

// The id of the medium a string value names; fails listing the defined media when there is none.
MediumId readMediumName(const JsonReader& json, const std::vector<Medium>& media);

}  // namespace dropscope
