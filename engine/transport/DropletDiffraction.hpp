#pragma once

#include "geometry/Shape.hpp"
#include "optics/Diffraction.hpp"

#include <optional>
#include <string_view>

namespace dropscope {

// Whether photons are diffracted by droplets (docs/transport.md, "Diffraction"): `None` is ray optics alone;
// `Fraunhofer` turns photons that pass a sphere or an ellipsoid within its halo (OpticalScene::firstHaloPass)
// by the Airy pattern of its projected outline.
enum class DiffractionModel { None, Fraunhofer };

std::string_view diffractionModelName(DiffractionModel model);  // "none", "fraunhofer"

// The outline of `shape` seen along `direction`: a sphere's disk, an ellipsoid's projected ellipse; nothing
// for the shapes that are not diffracted (boxes, parametric and implicit shapes).
std::optional<ProjectedEllipse> projectedOutline(const Shape& shape, const Direction& direction);

}  // namespace dropscope
