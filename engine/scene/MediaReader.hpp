#pragma once

#include "geometry/Shape.hpp"
#include "scene/JsonReader.hpp"
#include "scene/Medium.hpp"

#include <vector>

namespace dropscope {

// The "media" object: {name: {"n": ..., "kappa" | "sigma": ...}}, in file order. Absorption per
// scene unit is computed from kappa with the wavelength expressed in the scene unit.
std::vector<Medium> readMedia(const JsonReader& json, double wavelengthInSceneUnits);

// The id of the medium a string value names; fails listing the defined media when there is none.
MediumId readMediumName(const JsonReader& json, const std::vector<Medium>& media);

}  // namespace dropscope
