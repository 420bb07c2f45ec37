#pragma once

#include "geometry/Vector.hpp"

#include <string_view>

namespace dropscope {

enum class SourceType { Beam, Ray, PointSource };

std::string_view sourceTypeName(SourceType type);

// Where photons come from. beam: uniform over a disk of `radius` perpendicular to `direction`;
// ray: a pencil along `direction`; point: isotropic from `origin` (direction unused).
struct Source {
    SourceType type = SourceType::Ray;
    Point origin = Point::Zero();
    Direction direction{0.0, 0.0, 1.0};
    double radius = 0.0;
};

}  // namespace dropscope
