#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/Vector.hpp"
#include "geometry/parametric/ParametricBase.hpp"

#include <vector>

namespace dropscope {

// One crossing of a ray with a placed parametric surface.
struct RayCrossing {
    double s = 0.0;  // distance along the (unit) ray direction
    double u = 0.0;  // where on the base surface, folded into the domain
    double v = 0.0;
    double cosine = 0.0;      // ray direction . outward unit normal (placed frame): < 0 entering, > 0 leaving
    bool degenerate = false;  // at a degenerate point of the parametrisation (a pole): cosine from the normal
                              // ParametricBase::outwardNormal finds there (0 if none), less reliable
};

// Every crossing with s >= sMin of the ray p + s d (d unit) with the surface M r(u, v) + r0 of `base` placed by
// `transform`, nearest first. Each crossing appears once: roots found by neighbouring cells are merged, and an
// in-and-out within kDuplicateRootBands bands (a touch) is dropped. `band` is the placed shape's surface band.
//
// How (seed 000 1.4.7): the ray is mapped to the base frame, p' = M^-1 (p - r0), d' = M^-1 d (s is the same in
// both frames), and the quadtree of the base is descended with a slab test on each cell box. In each leaf the ray
// meets, F(u, v, s) = p' + d' s - r(u, v) = 0 (eq. 1.76 multiplied by M^-1: the same roots, and the same Newton
// iterates, as Newton is invariant under a linear change of the equations) is solved with the Jacobian
// [-r_u, -r_v, d'] (eq. 1.77 likewise), seeded where the ray meets the leaf's two corner triangles (else the
// centre) and kept within the leaf enlarged by a margin. When the ray is transverse to all normals of that
// region the patch is a graph along d', so a root found there is its only one; otherwise, or when Newton fails,
// the cell is split (its sub-boxes computed on the fly) down to kRayMaxRefinement levels below the leaf. What is
// still missed at that depth is a graze: a touch, which counts as no hit.
std::vector<RayCrossing> findRayCrossings(const ParametricBase& base, const AffineTransform& transform, const Point& p,
                                          const Eigen::Vector3d& d, double sMin, double band);

}  // namespace dropscope
