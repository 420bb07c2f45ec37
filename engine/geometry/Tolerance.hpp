#pragma once

#include <limits>

// Every numerical tolerance of the geometry, in one place. docs/geometry.md explains the policy.
// The parametric and implicit families' own tolerances (cells, Newton, quadrature, root finding) are in
// parametric/SurfaceTolerance.hpp, parametric/ParametricShapeTolerance.hpp and implicit/ImplicitTolerance.hpp.
namespace dropscope::tolerance {

// Half-width of the band around a surface inside which a point counts as "on the surface",
// relative to the shape's own size (radius, smallest semi-axis, longest box edge). Hit points computed
// as p + d*s carry a few ulps of relative error from the quadratic solve; 1e-9 leaves a margin of
// ~10^6 over that, while staying far below any physically meaningful length (a 1 mm droplet gets a 1 pm
// band).
inline constexpr double kSurfaceRelative = 1e-9;

// Absolute coordinates are rounded to ~|x|*eps; a droplet far from the origin must widen its band by
// that much, or its own hit points would fall outside it. 64 ulps covers the handful of roundings
// between a ray origin and a stored hit point.
inline constexpr double kCoordinateRelative = 64.0 * std::numeric_limits<double>::epsilon();

// Matrices read from a scene (an ellipsoid's M, a rotation) must be symmetric / orthonormal up to
// this relative deviation: loose enough for values written with ~10 significant digits, tight enough
// that a typo is caught.
inline constexpr double kMatrixRelative = 1e-10;

// Largest accepted ratio of an ellipsoid's longest to shortest semi-axis. Eigenvalues of M come out
// of the symmetric eigensolver with absolute error ~eps*lambda_max; at a ratio of 1e6 (eigenvalue ratio
// 1e12) the smallest is still known to ~1e-4 relative, beyond that it is noise.
inline constexpr double kMaxSemiAxisRatio = 1e6;

// A box moved by a translation gets its corners back as center +- half edge, which can change its edge
// lengths by a few ulps; edges that differ by no more than this, relative to the longest, are the same
// box moved (Box::sameFormAs).
inline constexpr double kMovedEdgeRelative = 1e-12;

// Band half-width, in length units, of a shape of characteristic size `size` whose coordinates
// are up to `coordinateMagnitude` in absolute value.
inline constexpr double surfaceBand(double size, double coordinateMagnitude) {
    return kSurfaceRelative * size + kCoordinateRelative * coordinateMagnitude;
}

}  // namespace dropscope::tolerance
