#pragma once

#include "edit/SceneDocument.hpp"

#include <string>

namespace dropscope::gui {

// The detectors the Detectors panel adds, placed from the bounds of the scene's shapes (render::sceneBounds)
// and its first source's direction (+z without one; a point source's: from it to the shapes' centre):
//  plane "screen": 1.5 bounding radii beyond the centre along that direction, facing the light (normal against
//    it), 3 radii square, 64 x 64 pixels;
//  far_field "sky": looking along that direction (it sees the light scattered back towards the source, where
//    the rainbows are), equidistant, 120 degrees across, 64 x 64 pixels;
//  shape_absorption "absorbed".
// Each named with the first of NAME, NAME-2, NAME-3, ... the document does not use.
Detector defaultDetector(const SceneDocument& document, DetectorType type);

// `base`, or `base-2`, `base-3`, ...: the first no detector of the document has.
std::string unusedDetectorName(const SceneDocument& document, const std::string& base);

}  // namespace dropscope::gui
