#pragma once

#include "scene/JsonReader.hpp"
#include "scene/Source.hpp"

namespace dropscope {

// One element of "sources": beam {origin, direction, radius}, ray {origin, direction}, point {origin}; beams
// and rays take an optional "polarisation" (docs/scene-format.md, "Sources").
Source readSource(const JsonReader& json);

}  // namespace dropscope
