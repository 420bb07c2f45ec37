#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/SurfaceMesh.hpp"
#include "geometry/implicit/ImplicitFunction.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <mutex>
#include <vector>

namespace dropscope {

// A numerical integral and an estimate of its absolute error.
struct IntegralEstimate {
    double value = 0.0;
    double errorEstimate = 0.0;
};

// Volume and surface area of one body, integrated together along the same lines.
struct BodyIntegrals {
    IntegralEstimate volume;
    IntegralEstimate area;
};

// Certified bounds on the greatest value of a linear function over a body: lower <= max <= upper.
struct ExtremeBounds {
    double lower = 0.0;
    double upper = 0.0;
};

// What every shape built on one implicit function shares, computed once (lazily, thread-safe) per
// function: the padded base bounds, the surface band of the base frame, the tessellation, the surface
// cover, and the base volume and area.
class ImplicitBase {
public:
    // Throws std::invalid_argument on a null function.
    explicit ImplicitBase(std::shared_ptr<const ImplicitFunction> function);

    const ImplicitFunction& function() const { return *function_; }
    // The function's bounds padded by tolerance::implicit::kBoundsPaddingRelative: f > 0 on this box.
    const Eigen::AlignedBox3d& bounds() const { return bounds_; }
    // Surface band of the base frame (characteristic length, coordinates of the bounds).
    double band() const { return band_; }

    // Marching tetrahedra on a kMeshCells^3 grid of the bounds (each cube split into 6 tetrahedra).
    const SurfaceMesh& mesh() const;
    // Boxes (from a Lipschitz subdivision of the bounds) that together contain the whole surface.
    const std::vector<Eigen::AlignedBox3d>& surfaceCover() const;
    // The base body's volume and area with error estimates: convexBodyIntegrals (ConvexBody.hpp) when
    // the function is convex, else bodyIntegrals with the identity.
    const BodyIntegrals& integrals() const;

private:
    std::shared_ptr<const ImplicitFunction> function_;
    Eigen::AlignedBox3d bounds_;
    double band_;
    mutable std::once_flag meshOnce_;
    mutable SurfaceMesh mesh_;
    mutable std::once_flag coverOnce_;
    mutable std::vector<Eigen::AlignedBox3d> cover_;
    mutable std::once_flag integralsOnce_;
    mutable BodyIntegrals integrals_;
};

// Volume and area of the placed body {r : f(M^-1 (r - r0)) <= 0} (in world units) by line integrals.
// Lines parallel to each world axis e_k through the midpoints of an N x N grid on the faces of
// `worldBounds`; along each, the root finder gives every crossing.
//   volume = integral over the face of the inside length (each axis gives one estimate; their mean);
//   area   = sum_k integral over lines along e_k of sum over crossings of |n_k|,
// because a surface element dS with unit normal n projects onto the plane normal to e_k with area
// |n_k| dS and each of its points is crossed by one line: the k-th integral is the surface integral of
// n_k^2, and sum_k n_k^2 = 1. Computed with N and 2N lines (N = `lines`); the 2N values are returned,
// with error estimates kIntegralSafety * |I(2N) - I(N)| (for the volume, at least that times the
// spread of the three axes' estimates): the midpoint rule converges like ~N^-1.5 (the inside length
// has a square-root edge at the silhouette), so the N-vs-2N difference exceeds the 2N error, up to the
// erratic lattice effects the safety factor covers (ImplicitTolerance.hpp).
// `baseBounds` (base frame) and `worldBounds` must both contain the body; lines are clipped to the first
// and laid over the faces of the second (the tighter it is, the more lines meet the body).
BodyIntegrals bodyIntegrals(const ImplicitFunction& f, const AffineTransform& transform,
                            const Eigen::AlignedBox3d& baseBounds, const Eigen::AlignedBox3d& worldBounds, double band,
                            int lines);

// Certified branch and bound for max of ell . r over the body f <= 0 inside `bounds` (base frame):
// best-first octree subdivision; a cell can hold surface only if |f(centre)| <= L * half-diagonal (a
// linear function's maximum over a compact body lies on its surface, so other cells are dropped); a
// cell's upper bound is ell . centre + |ell| . half-extents, and centres with f <= 0 give lower bounds.
// Stops when upper - lower <= tolerance (or after kExtremeMaxCells cells, with looser bounds).
ExtremeBounds maximumOverBody(const ImplicitFunction& f, const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& ell,
                              double tolerance);

}  // namespace dropscope
