#pragma once

#include "scene/Detector.hpp"
#include "scene/JsonReader.hpp"

#include <vector>

namespace dropscope {

// The scene's "detectors": a list of plane, far_field and shape_absorption detectors with unique names
// (docs/scene-format.md, "Detectors"). Throws SceneError at the JSON path of the bad value.
std::vector<Detector> readDetectors(const JsonReader& json);

}  // namespace dropscope
