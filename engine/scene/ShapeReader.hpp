#pragma once

#include "geometry/Shape.hpp"
#include "scene/JsonReader.hpp"
#include "scene/Medium.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dropscope {

struct NamedShape {
    std::unique_ptr<Shape> shape;
    std::string name;  // empty when unnamed
};

// One element of "shapes": sphere, ellipsoid or box, with its medium resolved against `media`.
NamedShape readShape(const JsonReader& json, const std::vector<Medium>& media);

}  // namespace dropscope
