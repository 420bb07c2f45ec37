#pragma once

#include "geometry/Shape.hpp"

#include <Eigen/Core>

namespace dropscope {

class Box;
class Sphere;
class Ellipsoid;

// Positive volume of intersection between any two shapes; symmetric. Touching within the surface
// bands is not overlapping. Shape::overlaps forwards here.
bool shapesOverlap(const Shape& a, const Shape& b);

bool boxesOverlap(const Box& a, const Box& b);
bool spheresOverlap(const Sphere& a, const Sphere& b);         // seed eq. 1.6
bool sphereOverlapsBox(const Sphere& sphere, const Box& box);  // seed eqs. 1.7-1.8

// Gilitschenski's K(lambda) test (seed eq. 1.34) for the ellipsoids
// (r - c_i) . inv(shape_i) (r - c_i) <= 1, i.e. shape_i = M_i^{-1}.
// Returns max over lambda in (0,1) of dr . (shapeA/lambda + shapeB/(1-lambda))^{-1} dr,
// which is 1 - min K: below 1 the two ellipsoids overlap, 1 means they touch. Throws
// std::invalid_argument when a shape matrix is not positive definite.
double gilitschenskiMaximum(const Eigen::Vector3d& centerA, const Eigen::Matrix3d& shapeA,
                            const Eigen::Vector3d& centerB, const Eigen::Matrix3d& shapeB);
bool ellipsoidsOverlap(const Ellipsoid& a, const Ellipsoid& b);
bool ellipsoidOverlapsSphere(const Ellipsoid& ellipsoid, const Sphere& sphere);

// Minimum over the box of (x - c) . M (x - c), by Eberly's feature tests (seed eqs. 1.35-1.56):
// 0 when the ellipsoid centre lies in the box (not the seed's box-centroid test, which is
// incomplete), else the least over the 8 vertices, the 12 edges and the 6 faces.
double minimumQuadraticFormOverBox(const Eigen::Vector3d& center, const Eigen::Matrix3d& m, const Box& box);
bool ellipsoidOverlapsBox(const Ellipsoid& ellipsoid, const Box& box);

}  // namespace dropscope

namespace dropscope {

// Two shapes of which at least one is parametric or implicit: a conservative test through the surface
// covers (GeneralOverlap.cpp): never misses an overlap, may report shapes that only come closer than
// the cover's cells, or touch. Symmetric.
bool generalShapesOverlap(const Shape& a, const Shape& b);

}  // namespace dropscope
