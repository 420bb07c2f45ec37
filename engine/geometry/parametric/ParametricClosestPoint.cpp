#include "geometry/parametric/ParametricClosestPoint.hpp"

#include "geometry/parametric/ParametricShapeTolerance.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace dropscope {

namespace tp = tolerance::parametric;

namespace {

struct Bounds {
    double u0, u1, v0, v1;
    // The side is a pole of the domain: steps towards it only go half-way, so that the iteration never lands on
    // the pole, where r_v = 0 would freeze v (a point near the pole seen from the wrong v would then be stuck).
    bool poleU0 = false, poleU1 = false, poleV0 = false, poleV1 = false;
};

// x + dx kept in [lo, hi]: clamped, or half-way to a pole side.
double limited(double x, double dx, double lo, double hi, bool poleLo, bool poleHi) {
    if (x + dx < lo) return poleLo ? x + 0.5 * (lo - x) : lo;
    if (x + dx > hi) return poleHi ? x + 0.5 * (hi - x) : hi;
    return x + dx;
}

Bounds searchRegion(const ParametricBase& base, const ParameterCell& cell) {
    const ParameterDomain& dom = base.domain();
    const double mu = tp::kClosestPointRegionMargin * cell.width();
    const double mv = tp::kClosestPointRegionMargin * cell.height();
    Bounds b{cell.u0 - mu, cell.u1 + mu, cell.v0 - mv, cell.v1 + mv};
    const std::array<bool, 4> poles = base.poles();
    if (!base.surface().periodicInU()) {
        b.poleU0 = b.u0 <= dom.u0 && poles[0];
        b.poleU1 = b.u1 >= dom.u1 && poles[1];
        b.u0 = std::max(b.u0, dom.u0);
        b.u1 = std::min(b.u1, dom.u1);
    }
    if (!base.surface().periodicInV()) {
        b.poleV0 = b.v0 <= dom.v0 && poles[2];
        b.poleV1 = b.v1 >= dom.v1 && poles[3];
        b.v0 = std::max(b.v0, dom.v0);
        b.v1 = std::min(b.v1, dom.v1);
    }
    return b;
}

// Newton on 1/2 |p - M r(u, v) - r0|^2 (eqs. 1.74, 1.75) with Levenberg-Marquardt damping, projected onto the
// region (an active-set projected Newton). The full Hessian J^T J - sum_k R_k H_k (H_k of seed 1.4, through M) rather
// than Gauss-Newton's J^T J: far from the surface (p near a sphere's centre) the residual is as large as the curvature
// radius and Gauss-Newton would crawl.
SurfaceProjection leastSquares(const ParametricBase& base, const AffineTransform& transform, const Point& p,
                               const ParameterCell& cell) {
    const Bounds region = searchRegion(base, cell);
    const Eigen::Matrix3d& m = transform.matrix();
    double u = cell.uMid();
    double v = cell.vMid();
    SurfaceJet jet = base.jet(u, v);
    Eigen::Vector3d residual = p - transform.apply(jet.r);
    double cost = residual.squaredNorm();
    double damping = tp::kClosestPointInitialDamping;
    const double stepFloor = tp::kClosestPointStepRelative * std::max(cell.width(), cell.height());
    for (int iteration = 0; iteration < tp::kClosestPointMaxIterations && cost > 0.0; ++iteration) {
        const Eigen::Vector3d a = m * jet.ru;
        const Eigen::Vector3d b = m * jet.rv;
        const Eigen::Vector2d gradient(-a.dot(residual), -b.dot(residual));  // of cost / 2
        const Eigen::Vector2d w = base.wrap(u, v);
        const SurfaceHessians h = base.surface().hessians(w.x(), w.y());
        const Eigen::Vector3d pulled = m.transpose() * residual;
        Eigen::Matrix2d hessian;
        hessian << a.dot(a) - pulled.dot(h.ruu), a.dot(b) - pulled.dot(h.ruv), a.dot(b) - pulled.dot(h.ruv),
            b.dot(b) - pulled.dot(h.rvv);
        const double scale = std::max(
            {a.squaredNorm() + b.squaredNorm(), std::abs(hessian.trace()), std::numeric_limits<double>::min()});
        // Marquardt's damping, per parameter (|M r_u|^2, |M r_v|^2) rather than one scale for both: next to a pole
        // |r_v| is ~ the distance to it, and a damping sized by |r_u| would freeze v there (steps in v below the
        // rounding of r), leaving the iterate far above the surface band from the true nearest point.
        const Eigen::Vector2d dampingScale(std::max(a.squaredNorm(), tp::kClosestPointDampingFloor * scale),
                                           std::max(b.squaredNorm(), tp::kClosestPointDampingFloor * scale));
        // Projected Newton's active set: a parameter on a side of the region that the descent direction pushes
        // further out stays there; the step is solved for the others (without this, a Newton step pointing out
        // of a corner would stop the iteration at the corner).
        const bool fixU = (u <= region.u0 && gradient.x() > 0.0) || (u >= region.u1 && gradient.x() < 0.0);
        const bool fixV = (v <= region.v0 && gradient.y() > 0.0) || (v >= region.v1 && gradient.y() < 0.0);
        if (fixU && fixV) break;  // a corner where the region holds the minimum
        bool improved = false;
        double moved = 0.0;
        while (damping < tp::kClosestPointMaxDamping) {
            Eigen::Vector2d step = Eigen::Vector2d::Zero();
            if (fixU || fixV) {
                const int k = fixU ? 1 : 0;
                const double curvature = hessian(k, k) + damping * dampingScale[k];
                if (!(curvature > 0.0)) {
                    damping = std::max(10.0 * damping, tp::kClosestPointInitialDamping);
                    continue;
                }
                step[k] = -gradient[k] / curvature;
            } else {
                const Eigen::Matrix2d damped = hessian + damping * Eigen::Matrix2d(dampingScale.asDiagonal());
                const Eigen::LLT<Eigen::Matrix2d> factor(damped);
                if (factor.info() != Eigen::Success) {
                    damping = std::max(10.0 * damping, tp::kClosestPointInitialDamping);
                    continue;
                }
                step = -factor.solve(gradient);
            }
            const double nu = limited(u, step.x(), region.u0, region.u1, region.poleU0, region.poleU1);
            const double nv = limited(v, step.y(), region.v0, region.v1, region.poleV0, region.poleV1);
            moved = std::hypot(nu - u, nv - v);
            if (!(moved > stepFloor)) break;
            const SurfaceJet trial = base.jet(nu, nv);
            const Eigen::Vector3d trialResidual = p - transform.apply(trial.r);
            const double trialCost = trialResidual.squaredNorm();
            if (trialCost < cost) {
                u = nu;
                v = nv;
                jet = trial;
                residual = trialResidual;
                cost = trialCost;
                damping *= 0.1;
                improved = true;
                break;
            }
            damping = std::max(10.0 * damping, tp::kClosestPointInitialDamping);
        }
        if (!improved || !(moved > stepFloor)) break;
    }
    // The poles themselves, which the iteration only approaches.
    const auto tryPoint = [&](double pu, double pv) {
        const double poleCost = (p - transform.apply(base.surface().point(pu, pv))).squaredNorm();
        if (poleCost < cost) {
            u = pu;
            v = pv;
            cost = poleCost;
        }
    };
    if (region.poleU0) tryPoint(region.u0, cell.vMid());
    if (region.poleU1) tryPoint(region.u1, cell.vMid());
    if (region.poleV0) tryPoint(cell.uMid(), region.v0);
    if (region.poleV1) tryPoint(cell.uMid(), region.v1);
    const Eigen::Vector2d folded = base.wrap(u, v);
    return {folded.x(), folded.y(), std::sqrt(cost)};
}

}  // namespace

SurfaceProjection closestSurfacePoint(const ParametricBase& base, const AffineTransform& transform, const Point& p,
                                      double cutoff) {
    SurfaceProjection best;
    if (!p.allFinite()) return best;
    const Point pBase = transform.applyInverse(p);
    const double smallestScale = transform.classification().singularValues[2];
    // Two lower bounds on the distance from p to the placed patch of a box; the larger is used.
    const auto lowerBound = [&](const Eigen::AlignedBox3d& box) {
        return std::max(smallestScale * box.exteriorDistance(pBase), transform.applyToBox(box).exteriorDistance(p));
    };
    const std::vector<CellNode>& nodes = base.nodes();
    using Entry = std::pair<double, std::int32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    queue.emplace(lowerBound(nodes.front().patch.box), 0);
    while (!queue.empty()) {
        const auto [bound, index] = queue.top();
        queue.pop();
        if (bound > std::min(best.distance, cutoff)) break;
        const CellNode& node = nodes[static_cast<std::size_t>(index)];
        if (node.isLeaf()) {
            const SurfaceProjection candidate = leastSquares(base, transform, p, node.patch.cell);
            if (candidate.distance < best.distance) best = candidate;
            continue;
        }
        for (std::int32_t k = 0; k < node.childCount; ++k) {
            const std::int32_t child = node.firstChild + k;
            const double childBound = lowerBound(nodes[static_cast<std::size_t>(child)].patch.box);
            if (childBound <= std::min(best.distance, cutoff)) queue.emplace(childBound, child);
        }
    }
    if (best.distance > cutoff) best = SurfaceProjection{};
    return best;
}

}  // namespace dropscope
