#pragma once

#include "geometry/Vector.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace dropscope {

// Triangles approximating a closed surface: what the renderer draws for parametric and implicit
// shapes. Every vertex lies on the surface (within the shape's surface band); normals are unit and
// outward; triangles are counter-clockwise seen from outside.
struct SurfaceMesh {
    std::vector<Point> vertices;
    std::vector<Eigen::Vector3d> normals;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace dropscope
