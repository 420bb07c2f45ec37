#pragma once

#include <limits>

// The numerical tolerances of ParametricShape and what it shares through ParametricBase: the cell tree
// over the parameter domain, ray crossings, closest points, the mesh.
namespace dropscope::tolerance::parametric {

// --- Cell tree (ParametricBase) ------------------------------------------------------------------------

// Each cell is sampled on a kCellSamples x kCellSamples grid (corners, edge midpoints, centre and the
// quarter points): its box, normal cone and Newton seeds come from these points.
inline constexpr int kCellSamples = 5;
// Cells split on the fly below the leaves (ray crossings) use 3 x 3 samples: the padding measured from them is
// ~4x larger, the cost 64% lower.
inline constexpr int kSubCellSamples = 3;

// Sampled maxima of |r_uu|, |r_uv|, |r_vv| over a cell are multiplied by this before they bound how far
// the surface strays from its samples, (h_u^2 |r_uu| + 2 h_u h_v |r_uv| + h_v^2 |r_vv|) / 8: sampling
// misses the peaks between samples; a factor 2 covers a second derivative that varies by 100% across a
// cell, far more than any cell of the tree sees on a smooth surface.
inline constexpr double kCurvatureSafety = 2.0;

// Second derivatives need not be bounded: the ellipsoid preset's r_uu grows like (1 - u^2)^(-3/2) at its
// poles, so sampled maxima say nothing there. The padding is therefore never less than this multiple of
// the largest deviation actually measured between samples twice as far apart (the midpoint against the
// mean of its neighbours). For a smooth surface that deviation is 4x the one between neighbouring samples;
// for a square-root pole it is still ~1.2x the largest deviation within a sub-cell, and 1.5 adds margin.
inline constexpr double kMeasuredDeviationSafety = 1.5;

// Every box is padded by this fraction of the surface's characteristic length on top: rounding in the
// samples (~1e-16) and the surface band (1e-9 relative) are far below it; it costs nothing in efficiency.
inline constexpr double kBoxPaddingRelative = 1e-7;

// The half-angle of the cone around the sampled normals is this multiple of the largest sampled angle:
// Newton's region is the cell enlarged by kNewtonRegionMargin on every side, whose normals spread ~1.5x
// further than the cell's, plus a margin for the variation between samples.
inline constexpr double kNormalSpreadSafety = 2.0;

// The tree splits a cell (into four) until its normals spread by at most this half-angle (radians) and
// its box diagonal is at most kLeafSizeRelative of the characteristic length, at least kLeafMinDepth and at
// most kLeafMaxDepth times. A spread of 0.3 rad (cone sine ~0.56 with the safety) lets ~80% of random rays
// take the single-Newton path in a leaf; depth 7 (128 x 128 cells) bounds the tree at ~22000 nodes.
inline constexpr double kLeafNormalSpread = 0.3;
inline constexpr double kLeafSizeRelative = 0.125;
inline constexpr int kLeafMinDepth = 2;
inline constexpr int kLeafMaxDepth = 7;

// A cell splits along a parameter only when its extent along it (the longer of its two edges, between corners)
// is at least this fraction of its extent along the other: near a pole, where one parameter's edges shrink to
// nothing, cells split across the pole only (a quadtree would pile up slivers that all contain the pole).
inline constexpr double kSplitLengthRatio = 0.5;

// r_u x r_v is taken as degenerate (its direction undefined) when its length is below this fraction of
// |r_u| |r_v|: r_u and r_v within 1e-8 rad of parallel, or either zero (a pole). The direction of the cross
// product carries a relative error ~eps / that sine, so 1e-8 still leaves ~1e-8 accuracy.
inline constexpr double kDegenerateRatio = 1e-8;

// At a pole (an edge of the domain collapsed to one point) the normal is the mean of kPoleRingSamples normals
// this fraction of the domain's width inside the edge: for a square-root parametrisation (the ellipsoid preset)
// a ring ~1.4e-5 rad from the pole, for a polynomial one ~1e-10; the first-order tilts cancel in the mean.
inline constexpr double kPoleRingStep = 1e-10;
inline constexpr int kPoleRingSamples = 8;

// At any other degenerate point the normal is taken this fraction of the domain's width inside the domain
// (towards its centre), growing tenfold up to kDegenerateStepTries times if still degenerate there.
inline constexpr double kDegenerateStep = 1e-7;
inline constexpr int kDegenerateStepTries = 6;

// --- Ray crossings (ParametricRayIntersection) ----------------------------------------------------------

// Cells in which Newton fails (or the ray is near-tangent to the cell's normal cone) are split this many
// more times below a leaf before the ray is taken to miss them: ~1000x smaller than a leaf. There Newton starts
// from the corners too. What is still missed is a graze: a chord of ~1e-4 of the size or less, within ~1e-8
// of tangency, which counts as a touch (no hit). Only near-tangent rays go this deep.
inline constexpr int kRayMaxRefinement = 10;

// Newton (seed 000 eqs. 1.76, 1.77) may wander this fraction of the cell's size outside the cell before it
// gives up there; a root it finds in this margin is kept (a neighbour finds it too: duplicates merge).
inline constexpr double kNewtonRegionMargin = 0.25;

// Newton iterations per seed. Near a regular root convergence is quadratic (~5 iterations); the rest is
// for the square-root behaviour at an ellipsoid pole, where each limited step halves the distance to it.
inline constexpr int kNewtonMaxIterations = 60;

// Newton steps taken after |F| is within the band, while they still reduce it (quadratic convergence: 1-2
// suffice; near tangency s carries |F| / |cos| of error, so the last digits matter there).
inline constexpr int kNewtonPolishSteps = 3;

// Consecutive steps that had to be shortened to stay in the region before Newton gives up: 3 inside the
// domain (the root is a neighbour's); kNewtonMaxLimitedAtEdge at a non-periodic domain edge (a pole),
// where halving the distance to the edge 40 times reaches ~1e-12 of the cell.
inline constexpr int kNewtonMaxLimited = 3;
inline constexpr int kNewtonMaxLimitedAtEdge = 40;

// A root is accepted when |F| (eq. 1.76, in length units) is below this fraction of the surface band plus
// the rounding of p + s d (kRayRoundingUlps ulps of |p| + |s|): the hit point is then surely in the band.
inline constexpr double kRootResidualBands = 0.25;
inline constexpr double kRayRoundingUlps = 8.0 * std::numeric_limits<double>::epsilon();

// Two roots closer than this many bands along the ray are one crossing found twice (by neighbouring
// cells) when they cross the same way, a touch (in and out within the band: no crossing) when not.
inline constexpr double kDuplicateRootBands = 4.0;

// A ray starting on the surface ignores the crossing at its own start: roots with s at most this many bands
// (the analytic shapes use 1 band, see RayQuadric.hpp; 4 leaves room for the Newton residual).
inline constexpr double kOwnCrossingBands = 4.0;

// The 3x3 Newton system is singular when its determinant r_u . (r_v x d') is below this fraction of
// |r_u| |r_v| |d'|: the ray is tangent, or (u, v) sits on a degenerate point.
inline constexpr double kNewtonSingularRatio = 1e-13;
// ... and then (u, v) moves this fraction of the way towards the cell's centre before the next step: off a pole
// by far more than rounding, by far less than the cell.
inline constexpr double kNewtonSingularNudge = 0.01;

// --- Point location, closest points and normals (ParametricClosestPoint, ParametricShape) ---------------

// Parity along a ray is trusted only when every crossing meets the surface at |cos| above this (the
// world-frame angle between ray and normal) and none is at a degenerate point; else another direction is
// tried. 1e-3 is a ~0.06 degree graze, far from the ~1e-8 where Newton's roots lose digits.
inline constexpr double kParityMinCosine = 1e-3;

// Newton / Levenberg-Marquardt for the closest point (eqs. 1.74, 1.75): iterations, damping, and the relative
// step (in units of the cell) below which it has converged.
// 80 iterations: ~6 near a regular minimum, ~35 to approach a minimum 1e-6 from a pole by halving steps (the
// square-root parametrisation of the ellipsoid preset). The damping (relative to |M r_u|^2 + |M r_v|^2) shrinks tenfold
// after a successful step, grows tenfold after a failed one, and the run stops when it would exceed
// kClosestPointMaxDamping (steps ~1e-12 of a gradient step).
inline constexpr int kClosestPointMaxIterations = 80;
inline constexpr double kClosestPointInitialDamping = 1e-6;
inline constexpr double kClosestPointMaxDamping = 1e12;
inline constexpr double kClosestPointStepRelative = 1e-14;
// The damping is per parameter, relative to |M r_u|^2 and |M r_v|^2, but never relative to less than this fraction
// of their sum: where one of them vanishes (on a pole) the damped system stays positive definite; 1e-30 leaves
// parameters whose derivative is ~1e-15 of the other's (a point ~1e-15 of the size from a pole) still free to move.
inline constexpr double kClosestPointDampingFloor = 1e-30;

// Each leaf's search region is the leaf enlarged by this fraction of its size, so a closest point on a
// leaf's edge lies inside at least one region, where the projected iteration converges quadratically.
inline constexpr double kClosestPointRegionMargin = 0.1;

// normal(p) answers for p within this many surface bands of the surface ("a few bands"), e.g. hit points
// computed by another shape's rounding; farther away p is not on the surface.
inline constexpr double kNormalSearchBands = 16.0;

// --- Integrals and mesh (ParametricBase) -----------------------------------------------------------------

// Base area and signed volume (SurfaceIntegrals) to this relative accuracy.
inline constexpr double kIntegralRelative = 1e-10;

// Base area of a transformed shape under a non-similarity (eq. 1.68), computed when first asked.
inline constexpr double kTransformedAreaRelative = 1e-10;

// The base mesh has about this many grid quads (48 x 96), shared between u and v in proportion to the
// surface's extent along each, and at least kMeshMinDivisions per direction.
inline constexpr int kMeshQuads = 48 * 96;
inline constexpr int kMeshMinDivisions = 12;

// A mesh triangle with an edge shorter than this fraction of the characteristic length is degenerate
// (two corners on one pole): it is not emitted.
inline constexpr double kMeshCollapsedRelative = 1e-12;

// The orientation (the sign of the signed volume) must be clear: |volume| above this fraction of
// characteristicLength^3, else the surface is not closed (or is flat) and encloses nothing.
inline constexpr double kMinVolumeRelative = 1e-9;

}  // namespace dropscope::tolerance::parametric
