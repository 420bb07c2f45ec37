#pragma once

#include <cstddef>

// Every numerical tolerance and size of the implicit shapes (engine/geometry/implicit), in one place.
// The surface band itself is tolerance::surfaceBand (geometry/Tolerance.hpp); most values here are
// multiples of it.
namespace dropscope::tolerance::implicit {

// Superellipsoid exponents are accepted in [kMinExponent, kMaxExponent]. Above 2 the body is no longer
// convex: the surface grows cusps along the axes where the gradient of any defining function is
// unbounded, so no Lipschitz bound (and no safe root finder) exists. Small exponents make powers 2/e
// and sums up to 2^(e2/e1) that overflow at e ~ 2e-3 when evaluated directly; Superellipsoid.cpp
// factors out the largest term so all its powers stay in [0, 1], but below 0.1 (powers above 20) the
// shape is within a few per cent of its box and its rounded edges shrink below what the 48^3
// tessellation grid resolves: 0.1 is where the accuracy stays documented.
inline constexpr double kMinExponent = 0.1;
inline constexpr double kMaxExponent = 2.0;

// The base-frame bounds are padded by this fraction of their diagonal, so f > 0 strictly on the padded
// box even after rounding: a ray clipped to the box then starts and ends outside the body.
inline constexpr double kBoundsPaddingRelative = 1e-6;

// The root finder's smallest step, in surface bands. Two crossings closer than this along a ray (a
// graze, a sliver thinner than ~4 bands) may be stepped over: within the band that is a touch, not a
// passage through the body, and without a floor a tangent ray would never finish.
inline constexpr double kMinStepBands = 4.0;

// Crossings are refined to this fraction of the surface band: hit points then lie well inside the
// band (locatePoint says OnSurface), leaving the band's margin for the rounding of p + t d.
inline constexpr double kRefineBands = 1e-3;

// Safeguarded Newton falls back to bisection, which halves a bracket of at most the box diagonal:
// 200 iterations is far beyond the ~60 that reach any double resolution; the cap only guards NaNs.
inline constexpr int kMaxRefineIterations = 200;

// Over-relaxed stepping (Keinert et al., "Enhanced sphere tracing", 2014): try a step of 1.6 times the
// Lipschitz-safe one and keep it only when the two safe radii still cover it (so no guarantee is lost);
// 1.6 is their recommended value, saving ~30-50% of evaluations on oblique approaches.
inline constexpr double kOverRelaxation = 1.6;

// Convex ray searches (ConvexRaySearch.hpp): Newton converges quadratically at a transversal crossing
// but only linearly, by 1 - 1/k per step, at a tangent (k = 2) or at the contact of order k ~ 2/e with a
// superellipsoid's flat face (k = 20 at e = 0.1). An iteration whose Newton step is more than this
// fraction of the previous one is slow and also bisects the interval left, so every iteration at least
// halves either the step or that interval: bisection's own rate.
inline constexpr double kConvexSlowProgress = 0.5;
// Each iteration halves a step or interval from the bounds' size down to ~kRefineBands bands (1e-12 of
// the size): ~2 x 45 iterations at the very worst; measured at most ~70 samples (141 evaluations) per
// query. The cap only guards a function that is not convex after all (or inconsistent gradients); the
// search then falls back to RayRootFinder.
inline constexpr int kConvexRayIterations = 200;

// A ray starting on the surface ignores crossings within this many bands of its origin: they are the
// origin's own crossing, displaced by the band and rounding.
inline constexpr double kSelfCrossingBands = 8.0;

// normal(p) answers within this many surface bands of the surface (p + t d rounds to a few ulps off).
inline constexpr double kNormalBands = 4.0;

// Marching tetrahedra: grid cells along each axis of the base bounds (48^3 cubes, 6 tetrahedra each):
// ~10^4 triangles, enough for display, ~0.1 s once per base.
inline constexpr int kMeshCells = 48;

// Surface cover: subdivide the bounds (octree levels) until at least this many boxes survive the
// Lipschitz test or kCoverMaxDepth is reached: a few hundred to a few thousand boxes.
inline constexpr std::size_t kCoverMinBoxes = 400;
inline constexpr int kCoverMaxDepth = 7;

// Volume and area integrals of non-convex functions (blobs; convex ones use the radial Gauss-Legendre
// rule below): midpoint rule on N x N lines per axis and on 2N x 2N. Each line costs
// ~100 function evaluations (Lipschitz marching past the silhouette), so 24/48 (~8600 lines, ~0.2 s
// once per base) is the budget; relative errors are then ~1e-4. The silhouette's square-root edge makes
// the midpoint rule's convergence erratic (~N^-1.5 on average, not monotone), so the error estimate is
// kIntegralSafety times |I(2N) - I(N)| (2 fell short on a superellipsoid with exponents 0.5, 1.5).
// Flat faces (small exponents) converge only like 1/N: errors ~2e-3 there.
inline constexpr int kIntegralLines = 24;
inline constexpr double kIntegralSafety = 3.0;

// Convex bodies (ImplicitFunction::convexCentre) integrate instead over their radial parametrisation on
// 24 panels (ConvexBody.hpp), smooth inside each panel: tensor Gauss-Legendre with 12 and 24 nodes per
// side (~17000 radial roots, 1-6 Newton steps each: a few ms). The 24-node values are returned; as
// Gauss-Legendre converges geometrically once the panel's features are resolved, |I(24) - I(12)| is
// about the 12-node error and far above the 24-node one, so a safety factor of 1 is already honest
// (measured: the estimate exceeds the actual error 20 to 10^5 times over exponents 0.1..2). The floor,
// 1e-12 relative, covers rounding in the ~10^4-term sums when the two orders agree to all digits.
inline constexpr int kConvexIntegralOrder = 12;
inline constexpr double kConvexIntegralSafety = 1.0;
inline constexpr double kConvexIntegralFloor = 1e-12;
// Gauss-Legendre nodes by Newton on P_n: converged to rounding (1e-15) in ~3-5 steps from the
// asymptotic guesses; 100 only bounds the loop.
inline constexpr int kLegendreNewtonIterations = 100;
inline constexpr double kLegendreNodeTolerance = 1e-15;

// Certified extremes: the branch and bound stops when upper - lower <= this fraction of the bounds'
// diagonal. Lipschitz cells of the tolerance's size must tile the cap around the extreme point, so the
// cost grows like 1/tolerance: 2e-3 keeps it to a few ms per extreme. The reported (outward) bound is
// never inside the shape, only up to this much outside (a slightly larger octree box).
inline constexpr double kExtremeRelative = 2e-3;
// Safety cap on cells examined per extreme; when reached the (still certified) bounds are just looser.
inline constexpr std::size_t kExtremeMaxCells = 100000;

}  // namespace dropscope::tolerance::implicit
