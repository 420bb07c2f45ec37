#pragma once

#include "scene/Source.hpp"

#include <string>

namespace dropscope::gui {

// The polarisation reference of a beam or ray source is the parallel axis of the frame its state is given
// in, and must stay perpendicular to the source's direction (checkPolarisation). These keep it so when the
// direction changes, in the Fire panel, by the aim handle or by A.

// A unit reference perpendicular to `direction`: the coordinate axis least along it, projected across it
// (x for light along z), so it reads as an axis of the scene.
Eigen::Vector3d perpendicularReference(const Direction& direction);

// When the source is polarised and its reference is no longer perpendicular to its direction (within
// tolerance::kReferencePerpendicularCosine), or is zero: replaces it by its projection onto the plane
// perpendicular to the direction, or, when it lies (nearly) along the direction, by
// perpendicularReference. Returns what was done, for the status line; empty when nothing was.
std::string keepReferencePerpendicular(Source& source);

// Points the source along `direction` and keeps its reference perpendicular; returns what was done to the
// reference, as above.
std::string aimSource(Source& source, const Direction& direction);

}  // namespace dropscope::gui
