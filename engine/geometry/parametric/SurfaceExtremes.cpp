#include "geometry/parametric/SurfaceExtremes.hpp"

#include "geometry/parametric/BezierSurface.hpp"
#include "geometry/parametric/SurfaceTolerance.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace dropscope {

namespace {

namespace tol = tolerance::surface;

struct Axis {
    double lower;
    double upper;
    bool periodic;
    double width() const { return upper - lower; }
    // Onto the domain: clamped at a bound, wrapped along a periodic parameter.
    double project(double x) const {
        if (!periodic) return std::clamp(x, lower, upper);
        double y = std::fmod(x - lower, width());
        if (y < 0.0) y += width();
        return lower + y;
    }
};

// A box of the domain on which r is smooth: the whole domain, or one Bezier patch (r is only C0 across
// patch seams, where Newton would bounce; an extreme on a seam is on a piece's edge instead).
using Piece = std::array<Axis, 2>;

std::vector<Piece> smoothPieces(const ParametricSurface& surface) {
    const ParameterDomain d = surface.domain();
    const auto* bezier = dynamic_cast<const BezierSurface*>(&surface);
    if (!bezier) return {Piece{Axis{d.u0, d.u1, surface.periodicInU()}, Axis{d.v0, d.v1, surface.periodicInV()}}};
    std::vector<Piece> pieces;
    for (std::size_t r = 0; r < bezier->rows(); ++r)
        for (std::size_t c = 0; c < bezier->columns(); ++c) {
            const double u = static_cast<double>(r), v = static_cast<double>(c);
            pieces.push_back(Piece{Axis{u, u + 1.0, false}, Axis{v, v + 1.0, false}});
        }
    return pieces;
}

// Minimises F = sign * direction . r(u, v) over one piece: projected Newton (seed 000 1.4.1).
class Minimiser {
public:
    Minimiser(const ParametricSurface& surface, const Piece& piece, const Eigen::Vector3d& direction, double sign)
        : surface_(surface), direction_(sign * direction), axes_(piece) {
        maxStep_ = tol::kExtremeMaxStepFraction * std::min(axes_[0].width(), axes_[1].width());
    }

    double value(const Eigen::Vector2d& x) const { return direction_.dot(surface_.point(x[0], x[1])); }

    // The least F reached from `start`. Iterates stay strictly inside a bounded parameter's range
    // (each step goes at most kExtremeBoundaryFraction of the way to the bound): on an edge the
    // derivatives may be degenerate (an ellipsoid's poles, where r_u is unbounded and only its finite part
    // is returned) and would stall Newton there. An optimum on a bound is approached geometrically,
    // and the bound itself is tried at the end.
    double descend(Eigen::Vector2d x) const {
        double f = value(x);
        for (int iteration = 0; iteration < tol::kExtremeMaxIterations; ++iteration) {
            // seed 000 eqs. 1.65, 1.66: gradient and Hessian of F from r_u, r_v and the coordinate Hessians.
            const SurfaceJet jet = surface_.jet(x[0], x[1]);
            const SurfaceHessians h = surface_.hessians(x[0], x[1]);
            const Eigen::Vector2d g(direction_.dot(jet.ru), direction_.dot(jet.rv));
            Eigen::Matrix2d hessian;
            hessian << direction_.dot(h.ruu), direction_.dot(h.ruv), direction_.dot(h.ruv), direction_.dot(h.rvv);

            // Active set: a parameter next to a bound, with the gradient pointing out of the box, is held.
            std::array<bool, 2> free{};
            for (int k = 0; k < 2; ++k) {
                const Axis& a = axes_[static_cast<std::size_t>(k)];
                const double near = tol::kExtremeStepRelative * a.width();
                free[static_cast<std::size_t>(k)] =
                    a.periodic || !((x[k] - a.lower <= near && g[k] > 0.0) || (a.upper - x[k] <= near && g[k] < 0.0));
            }
            const Eigen::Vector2d step = newtonStep(g, hessian, free);
            if (step.isZero()) break;

            double next = 0.0;
            Eigen::Vector2d moved;
            if (!lineSearch(x, f, g, step, moved, next)) {
                // The Newton direction failed (a kink between patches, or the bounds turned it uphill):
                // try steepest descent before giving up.
                const Eigen::Vector2d descent(free[0] ? -g[0] : 0.0, free[1] ? -g[1] : 0.0);
                if (descent.isZero() || !lineSearch(x, f, g, descent * (maxStep_ / descent.norm()), moved, next)) break;
            }
            const Eigen::Vector2d delta = moved - x;
            x = Eigen::Vector2d(axes_[0].project(moved[0]), axes_[1].project(moved[1]));
            f = next;
            if (std::abs(delta[0]) <= tol::kExtremeStepRelative * axes_[0].width() &&
                std::abs(delta[1]) <= tol::kExtremeStepRelative * axes_[1].width())
                break;
        }
        // The bound an iterate has crept up to may be the optimum itself.
        Eigen::Vector2d snapped = x;
        for (int k = 0; k < 2; ++k) {
            const Axis& a = axes_[static_cast<std::size_t>(k)];
            if (a.periodic) continue;
            if (x[k] - a.lower <= tol::kExtremeSnapRelative * a.width()) snapped[k] = a.lower;
            if (a.upper - x[k] <= tol::kExtremeSnapRelative * a.width()) snapped[k] = a.upper;
        }
        return snapped == x ? f : std::min(f, value(snapped));
    }

private:
    // -(H + alpha I)^-1 g over the free parameters, alpha making H + alpha I positive definite with its
    // least eigenvalue large enough that the step stays within maxStep_ (a trust region).
    Eigen::Vector2d newtonStep(const Eigen::Vector2d& g, const Eigen::Matrix2d& hessian,
                               const std::array<bool, 2>& free) const {
        Eigen::Vector2d step = Eigen::Vector2d::Zero();
        if (free[0] && free[1]) {
            const double a = hessian(0, 0), b = hessian(0, 1), c = hessian(1, 1);
            const double radius = std::hypot(0.5 * (a - c), b);
            const double least = 0.5 * (a + c) - radius;
            const double norm = std::abs(0.5 * (a + c)) + radius;
            const double alpha = damping(least, norm, g.norm());
            const Eigen::Matrix2d damped = hessian + alpha * Eigen::Matrix2d::Identity();
            if (g.isZero() || !(damped.determinant() > 0.0)) return step;
            step = -damped.ldlt().solve(g);
        } else {
            for (int k = 0; k < 2; ++k) {
                if (!free[static_cast<std::size_t>(k)] || g[k] == 0.0) continue;
                const double curvature =
                    hessian(k, k) + damping(hessian(k, k), std::abs(hessian(k, k)), std::abs(g[k]));
                if (curvature > 0.0) step[k] = -g[k] / curvature;
            }
        }
        return step.allFinite() ? step : Eigen::Vector2d::Zero();
    }

    double damping(double least, double norm, double gradientNorm) const {
        const double floor = std::max(tol::kExtremeDampingRelative * norm, gradientNorm / maxStep_);
        return std::max(0.0, floor - least);
    }

    // Armijo backtracking along `step`, each bounded parameter held to kExtremeBoundaryFraction of its
    // distance to the bound it moves towards; `moved` is left unwrapped along a periodic parameter.
    bool lineSearch(const Eigen::Vector2d& x, double f, const Eigen::Vector2d& g, const Eigen::Vector2d& step,
                    Eigen::Vector2d& moved, double& next) const {
        double t = 1.0;
        for (int halving = 0; halving < tol::kArmijoMaxHalvings; ++halving, t *= 0.5) {
            Eigen::Vector2d y = x + t * step;
            for (int k = 0; k < 2; ++k) {
                const Axis& a = axes_[static_cast<std::size_t>(k)];
                if (a.periodic) continue;
                const double reach = tol::kExtremeBoundaryFraction;
                y[k] = std::clamp(y[k], x[k] - reach * (x[k] - a.lower), x[k] + reach * (a.upper - x[k]));
            }
            const double decrease = g.dot(y - x);
            if (!(decrease < 0.0)) continue;
            const double fy = value(Eigen::Vector2d(axes_[0].project(y[0]), axes_[1].project(y[1])));
            if (fy <= f + tol::kArmijoConstant * decrease) {
                moved = y;
                next = fy;
                return true;
            }
        }
        return false;
    }

    const ParametricSurface& surface_;
    Eigen::Vector3d direction_;
    std::array<Axis, 2> axes_{};
    double maxStep_ = 0.0;
};

// Nodes of the starting grid along one parameter: cell centres along a bounded one (a start never sits
// on a pole or an edge, where the derivatives may be degenerate; Newton still reaches the bound), evenly
// from the lower end along a periodic one.
std::vector<double> gridNodes(double lower, double upper, bool periodic) {
    const double width = upper - lower;
    const int n = std::max(tol::kExtremeMinGrid, tol::kExtremeGridPerUnit * static_cast<int>(std::ceil(width)));
    std::vector<double> nodes(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k)
        nodes[static_cast<std::size_t>(k)] =
            lower + width * (static_cast<double>(k) + (periodic ? 0.0 : 0.5)) / static_cast<double>(n);
    return nodes;
}

// The least value of sign * direction . r over the piece: the grid's local minima, the lowest polished by
// Newton.
double pieceMinimum(const ParametricSurface& surface, const Piece& piece, const Eigen::Vector3d& direction,
                    double sign) {
    const std::vector<double> us = gridNodes(piece[0].lower, piece[0].upper, piece[0].periodic);
    const std::vector<double> vs = gridNodes(piece[1].lower, piece[1].upper, piece[1].periodic);
    const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
    std::vector<double> values;
    values.reserve(us.size() * vs.size());
    for (const double u : us)
        for (const double v : vs) values.push_back(sign * direction.dot(surface.point(u, v)));
    const auto at = [&](int i, int j) { return values[static_cast<std::size_t>(i * nv + j)]; };

    std::vector<std::pair<double, std::array<int, 2>>> minima;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            best = std::min(best, at(i, j));
            bool isMinimum = true;
            for (int di = -1; di <= 1 && isMinimum; ++di)
                for (int dj = -1; dj <= 1 && isMinimum; ++dj) {
                    int ni = i + di, nj = j + dj;
                    if (piece[0].periodic) ni = (ni + nu) % nu;
                    if (piece[1].periodic) nj = (nj + nv) % nv;
                    if ((di == 0 && dj == 0) || ni < 0 || ni >= nu || nj < 0 || nj >= nv) continue;
                    isMinimum = at(i, j) <= at(ni, nj);
                }
            if (isMinimum) minima.push_back({at(i, j), {i, j}});
        }
    std::sort(minima.begin(), minima.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const Minimiser minimiser(surface, piece, direction, sign);
    const std::size_t starts = std::min(minima.size(), static_cast<std::size_t>(tol::kExtremeMaxStarts));
    for (std::size_t s = 0; s < starts; ++s) {
        const auto [i, j] = minima[s].second;
        const Eigen::Vector2d start(us[static_cast<std::size_t>(i)], vs[static_cast<std::size_t>(j)]);
        best = std::min(best, minimiser.descend(start));
    }
    return best;
}

}  // namespace

ExtremeRange extremeRange(const ParametricSurface& surface, const Eigen::Vector3d& direction) {
    if (!direction.allFinite()) return {std::nan(""), std::nan("")};
    ExtremeRange range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const Piece& piece : smoothPieces(surface)) {
        range.min = std::min(range.min, pieceMinimum(surface, piece, direction, 1.0));
        range.max = std::max(range.max, -pieceMinimum(surface, piece, direction, -1.0));
    }
    return range;
}

}  // namespace dropscope
