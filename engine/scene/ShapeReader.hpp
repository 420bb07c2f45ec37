#pragma once

#include "geometry/Shape.hpp"
#include "scene/GeneralShapeReader.hpp"
#include "scene/JsonReader.hpp"
#include "scene/Medium.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace dropscope {

struct NamedShape {
    std::unique_ptr<Shape> shape;
    std::string name;  // empty when unnamed
};

// The "min" and "max" corners of a box or region: two 3-vectors with min < max on every axis.
Eigen::AlignedBox3d readCorners(const JsonReader& json);

// One element of "shapes": sphere, ellipsoid, box, parametric or implicit, with its medium resolved
// against `media`. Parametric and implicit shapes with equal presets share their base through `cache`.
NamedShape readShape(const JsonReader& json, const std::vector<Medium>& media, BaseCache& cache);

}  // namespace dropscope
