#pragma once

#include "scene/JsonReader.hpp"
#include "scene/Source.hpp"

namespace dropscope {

// One element of "sources": beam {origin, direction, radius}, ray {origin, direction}, point {origin}.
Source readSource(const JsonReader& json);

}  // namespace dropscope
