#pragma once

#include <limits>

// The numerical tolerances of the parametric base surfaces, their integrals and extreme points
// (engine/geometry/parametric: ParametricSurface.cpp, the presets, SurfaceIntegrals, SurfaceExtremes).
namespace dropscope::tolerance::surface {

// --- Numeric derivatives (ParametricSurface::jet / ::hessians defaults) -------------------------------

// Step of the first-derivative differences, as a fraction of the domain's width in that parameter.
// A second-order difference has truncation error ~h^2 |r'''| and rounding error ~eps |r| / h; the sum is
// least at h ~ eps^(1/3) ~ 6e-6, where both are ~4e-11 relative.
inline constexpr double kFirstDerivativeStep = 6e-6;

// Step of the second-derivative differences (r_uu, r_uv, r_vv), as a fraction of the domain's width:
// truncation ~h^2 |r''''| against rounding ~eps |r| / h^2 balance at h ~ eps^(1/4) ~ 1.2e-4, both ~1e-8
// relative.
inline constexpr double kSecondDerivativeStep = 1.2e-4;

// --- Bezier nets -------------------------------------------------------------------------------------

// Neighbouring patches must share their edge control points, a pole edge must collapse to one point,
// within this fraction of the net's size (the largest edge of the control points' bounding box). Scene
// files write ~10 significant digits, so copies of one point differ by ~1e-10 relative; 1e-8 accepts
// those with a margin and still rejects any visible gap.
inline constexpr double kBezierEdgeRelative = 1e-8;

// --- Adaptive quadrature (SurfaceIntegrals) ---------------------------------------------------------

// Cells per unit of parameter along each direction to start from, and at least this many per
// direction: enough that the Gauss-Kronrod error estimate of every starting cell is meaningful (a
// single cell over a whole ellipsoid could see a smooth integrand as a near-constant by accident).
inline constexpr int kQuadratureMinInitialCells = 4;

// Upper bound on the number of cells one integral may split into (each costs 225 evaluations of the
// surface's jet): ~50 ms for a cheap surface. A surface that needs more returns its best value with an
// honest error estimate above the requested tolerance.
inline constexpr int kQuadratureMaxCells = 20000;

// The target error is never asked below this many ulps of the integral of |integrand| (the sum of the
// cells' absolute values): rounding in 225-point sums makes smaller estimates noise, and a signed
// integral (the volume) cancels to a value far below its terms.
inline constexpr double kQuadratureRoundoffFloor = 64.0 * std::numeric_limits<double>::epsilon();

// A cell is split along both directions when the smaller directional error estimate is at least this
// fraction of the larger one, else only along the worse direction (anisotropic integrands, e.g. a thin
// ellipsoid, then do not waste evaluations in the smooth direction).
inline constexpr double kQuadratureSplitBothRatio = 0.25;

// --- Extreme points (SurfaceExtremes) -----------------------------------------------------------------

// Starting grid on each smooth piece of the domain (the whole domain, or one Bezier patch): nodes per
// unit of parameter, and at least kExtremeMinGrid per direction. A droplet-like surface has a few local
// extremes along any direction, a bicubic patch at most a handful; 12 nodes per direction put a node in
// the basin of each.
inline constexpr int kExtremeGridPerUnit = 4;
inline constexpr int kExtremeMinGrid = 12;

// Newton runs are started from at most this many of the grid's local minima (the lowest first).
inline constexpr int kExtremeMaxStarts = 6;

// Levenberg-style damping: the Hessian gets alpha*I added until its least eigenvalue is at least this
// fraction of its norm (seed 000 1.4.1), so the Newton system is always safely positive definite.
inline constexpr double kExtremeDampingRelative = 1e-10;

// No Newton step moves further than this fraction of the domain's smallest width (alpha grows to cap
// it): a flat or linear stretch of the surface would otherwise send the step across the whole domain.
inline constexpr double kExtremeMaxStepFraction = 0.25;

// Armijo's sufficient-decrease constant (the usual small value: accept any step that realises this
// fraction of the decrease the gradient predicts).
inline constexpr double kArmijoConstant = 1e-4;

// Backtracking halvings before a line search gives up (2^-60 of a step is far below a parameter ulp).
inline constexpr int kArmijoMaxHalvings = 60;

// Newton iterations per start: quadratic convergence needs ~6 near a regular optimum; the rest is for
// the damped approach from a poor start and for the square-root behaviour of an ellipsoid near a pole.
inline constexpr int kExtremeMaxIterations = 200;

// A step goes at most this fraction of the way to a bound of a non-periodic parameter, so iterates
// stay inside, off degenerate edges such as an ellipsoid's poles (where r_u is unbounded). An optimum on
// the bound is then approached by a factor 10 per iteration, ~13 iterations to come within 1e-13 of it.
inline constexpr double kExtremeBoundaryFraction = 0.9;

// At the end of a run, a parameter within this fraction of the domain's width from a bound is also
// tried on the bound itself (the iterates only creep up to it); the better of the two values is kept.
inline constexpr double kExtremeSnapRelative = 1e-8;

// A run has converged when its step moves the parameters by less than this fraction of the domain's
// width: near a regular optimum the value then differs from the extreme by ~(1e-13)^2, and at a
// boundary optimum the step is already zero.
inline constexpr double kExtremeStepRelative = 1e-13;

}  // namespace dropscope::tolerance::surface
