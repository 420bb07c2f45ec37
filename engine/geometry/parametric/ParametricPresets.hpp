#pragma once

#include "geometry/Vector.hpp"
#include "geometry/parametric/ParametricSurface.hpp"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace dropscope {

// The base surfaces a scene file can name. Each throws std::invalid_argument naming the parameter
// when it is out of range.

// Preset "sphere" {radius}: the ellipsoid surface with three equal semi-axes.
std::shared_ptr<const ParametricSurface> makeSphereSurface(double radius);
// Preset "ellipsoid" {semi_axes}: axis-aligned semi-axes a, b, c along x, y, z.
std::shared_ptr<const ParametricSurface> makeEllipsoidSurface(const Eigen::Vector3d& semiAxes);
// Preset "torus" {major_radius, minor_radius}: about the z axis, 0 < minor_radius < major_radius.
std::shared_ptr<const ParametricSurface> makeTorusSurface(double majorRadius, double minorRadius);

// One bicubic control net: net[i][j], i along u, j along v (seed 003 1.2.1).
using BezierNet = std::array<std::array<Point, 4>, 4>;
// Preset "bezier" {patches}: rows of patches (patches[row][column]), row r covering u in [r, r+1],
// column c covering v in [c, c+1]. They must close up (BezierSurface.hpp says how).
std::shared_ptr<const ParametricSurface> makeBezierSurface(const std::vector<std::vector<BezierNet>>& patches);

}  // namespace dropscope
