#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/implicit/ImplicitBase.hpp"
#include "geometry/implicit/ImplicitFunction.hpp"

#include <Eigen/Geometry>

namespace dropscope {

// Where the ray centre + t u, t > 0, leaves a convex body (f convex, f(centre) < 0, f(centre + tOut u) > 0),
// and grad f there.
struct RadialExit {
    double t = 0.0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
};

// Newton from the outside end tOut: on a convex g(t) = f(centre + t u) the tangent at an outside point
// lies below g, so each Newton point is still outside (>= the root) and the iterates fall monotonically
// onto it, quadratically for a simple root; one step when f is a gauge minus 1 (g linear along the ray).
// A bracket [lo, hi] guards rounding (bisection when Newton leaves it). Stops when the step or the
// bracket is below `tolerance` (in t).
RadialExit radialExit(const ImplicitFunction& f, const Point& center, const Eigen::Vector3d& u, double tOut,
                      double tolerance);

// Volume and area of the convex body f <= 0 (base frame; the area also of its image under `transform`)
// from its radial parametrisation about `centre` (strictly inside). The box C +- H, H_i the larger distance
// from the centre to the faces of `bounds`, has 6 faces; each is split at the centre's coordinate planes
// into 4 quadrants, 24 panels (s, t) in [0, 1]^2 with ray directions u = H (sigma e_k + s e_i + t e_j) (signs
// per quadrant, H = diag). With lambda(s, t) the exit parameter and n the unit normal there:
//   dV = lambda^3 det H / 3 ds dt                 (the cone from the centre: Jacobian lambda'^2 det[u, u_s, u_t])
//   dA = lambda^2 det H / (u . n) ds dt           (dV = (r - C) . n dA / 3 with r - C = lambda u)
//   placed dA' = |det M| |M^-T n| dA              (Nanson's formula; docs/general-shapes.md).
// The panel edges are where the superellipsoids' rounded edges and non-smooth planes lie, so the
// integrands are smooth inside each panel and tensor Gauss-Legendre converges fast. Computed with
// `order` and 2 `order` nodes per panel side: the finer values, error estimates
// kConvexIntegralSafety * |I(2n) - I(n)| (ImplicitTolerance.hpp).
// The volume is returned in the base frame (|det M| scales it exactly); the area is the placed one.
BodyIntegrals convexBodyIntegrals(const ImplicitFunction& f, const Point& center, const Eigen::AlignedBox3d& bounds,
                                  const AffineTransform& transform, double band, int order);

}  // namespace dropscope
