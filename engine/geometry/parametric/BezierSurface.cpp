#include "geometry/parametric/BezierSurface.hpp"

#include "geometry/parametric/SurfaceTolerance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace dropscope {

namespace {

using Edge = std::array<Point, 4>;

// The cubic Bernstein basis B_0..B_3 (seed 003 1.1.4) and its first and second derivatives at t.
struct Bernstein {
    std::array<double, 4> b;
    std::array<double, 4> db;
    std::array<double, 4> ddb;
};

Bernstein bernstein(double t) {
    const double s = 1.0 - t;
    return {{s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t},
            {-3.0 * s * s, 3.0 * s * (1.0 - 3.0 * t), 3.0 * t * (2.0 - 3.0 * t), 3.0 * t * t},
            {6.0 * s, 6.0 * (3.0 * t - 2.0), 6.0 * (1.0 - 3.0 * t), 6.0 * t}};
}

// The patch holding parameter x (0 <= index < count; x = count belongs to the last) and x's offset in it.
std::pair<std::size_t, double> locate(double x, std::size_t count) {
    const double last = static_cast<double>(count - 1);
    const double index = std::clamp(std::floor(x), 0.0, last);
    return {static_cast<std::size_t>(index), x - index};
}

Edge bottomEdge(const BezierNet& net) { return net[0]; }
Edge topEdge(const BezierNet& net) { return net[3]; }
Edge leftEdge(const BezierNet& net) { return {net[0][0], net[1][0], net[2][0], net[3][0]}; }
Edge rightEdge(const BezierNet& net) { return {net[0][3], net[1][3], net[2][3], net[3][3]}; }

// Two edges are the same cubic when their control points coincide.
bool sameEdge(const Edge& a, const Edge& b, double tolerance) {
    for (std::size_t k = 0; k < 4; ++k)
        if (!((a[k] - b[k]).cwiseAbs().maxCoeff() <= tolerance)) return false;
    return true;
}

bool isPoint(const Edge& e, const Point& pole, double tolerance) {
    return std::all_of(e.begin(), e.end(),
                       [&](const Point& p) { return (p - pole).cwiseAbs().maxCoeff() <= tolerance; });
}

std::string name(std::size_t row, std::size_t column) {
    return "patches[" + std::to_string(row) + "][" + std::to_string(column) + "]";
}

}  // namespace

BezierSurface::BezierSurface(std::vector<std::vector<BezierNet>> patches) : patches_(std::move(patches)) { validate(); }

void BezierSurface::validate() {
    if (patches_.empty() || patches_.front().empty())
        throw std::invalid_argument("patches must hold at least one patch");
    const std::size_t nr = patches_.size();
    const std::size_t nc = patches_.front().size();
    Eigen::AlignedBox3d bounds;
    for (std::size_t r = 0; r < nr; ++r) {
        if (patches_[r].size() != nc)
            throw std::invalid_argument("patches[" + std::to_string(r) + "] has " + std::to_string(patches_[r].size()) +
                                        " patches, patches[0] has " + std::to_string(nc) +
                                        ": rows must be equally long");
        for (std::size_t c = 0; c < nc; ++c)
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j) {
                    const Point& p = patches_[r][c][i][j];
                    if (!p.allFinite())
                        throw std::invalid_argument(name(r, c) + ": control point [" + std::to_string(i) + "][" +
                                                    std::to_string(j) + "] is not finite");
                    bounds.extend(p);
                }
    }
    size_ = bounds.sizes().maxCoeff();
    if (!(size_ > 0.0)) throw std::invalid_argument("patches: all control points coincide");
    const double tol = tolerance::surface::kBezierEdgeRelative * size_;

    for (std::size_t r = 0; r < nr; ++r)
        for (std::size_t c = 0; c < nc; ++c) {
            const std::size_t left = (c + nc - 1) % nc;
            if (!sameEdge(leftEdge(patches_[r][c]), rightEdge(patches_[r][left]), tol))
                throw std::invalid_argument(name(r, c) + ": its left edge does not meet " + name(r, left) +
                                            "'s right edge" + (c == 0 ? " (the v seam does not close)" : ""));
            if (r > 0 && !sameEdge(bottomEdge(patches_[r][c]), topEdge(patches_[r - 1][c]), tol))
                throw std::invalid_argument(name(r, c) + ": its bottom edge does not meet " + name(r - 1, c) +
                                            "'s top edge");
        }

    // The u = 0 and u = rows edges: poles, or one periodic seam.
    const Point bottomPole = patches_.front().front()[0][0];
    const Point topPole = patches_.back().front()[3][0];
    bool bottomIsPole = true, topIsPole = true;
    for (std::size_t c = 0; c < nc; ++c) {
        bottomIsPole = bottomIsPole && isPoint(bottomEdge(patches_.front()[c]), bottomPole, tol);
        topIsPole = topIsPole && isPoint(topEdge(patches_.back()[c]), topPole, tol);
    }
    // A pole accepted within the tolerance is made exactly one point: r_v must vanish there exactly (see the
    // evaluation below), or r_u x r_v would point along the copies' rounding differences.
    const auto snapPole = [&](std::size_t row, std::size_t edgeRow, const Point& pole) {
        for (BezierNet& net : patches_[row])
            for (Point& q : net[edgeRow]) q = pole;
    };
    if (bottomIsPole) snapPole(0, 0, bottomPole);
    if (topIsPole) snapPole(nr - 1, 3, topPole);
    if (bottomIsPole && topIsPole) return;
    const auto bottomMessage = [&](std::size_t c) {
        return name(0, c) + ": its bottom edge (u = 0) is neither a single point (a pole) nor " + name(nr - 1, c) +
               "'s top edge (u = " + std::to_string(nr) + ")";
    };
    const auto topMessage = [&](std::size_t c) {
        return name(nr - 1, c) + ": its top edge (u = " + std::to_string(nr) +
               ") is neither a single point (a pole) nor " + name(0, c) + "'s bottom edge (u = 0)";
    };
    for (std::size_t c = 0; c < nc; ++c) {
        if (!bottomIsPole && !topIsPole) {
            if (!sameEdge(bottomEdge(patches_.front()[c]), topEdge(patches_.back()[c]), tol))
                throw std::invalid_argument(bottomMessage(c));
        } else if (!bottomIsPole && !isPoint(bottomEdge(patches_.front()[c]), bottomPole, tol)) {
            throw std::invalid_argument(bottomMessage(c));  // the other end is a pole: this one cannot meet it
        } else if (!topIsPole && !isPoint(topEdge(patches_.back()[c]), topPole, tol)) {
            throw std::invalid_argument(topMessage(c));
        }
    }
    periodicInU_ = true;
}

ParameterDomain BezierSurface::domain() const {
    return {0.0, static_cast<double>(rows()), 0.0, static_cast<double>(columns())};
}

// The sums below run over differences from one control point of each row (and from one row), not over the
// control points themselves: the Bernstein weights sum to 1 and their derivatives to 0 only up to rounding, so
// sum_j B_j'(t) net[i][j] over a row collapsed to a pole P would leave r_v ~ eps P instead of 0, whose direction
// (along P) is unrelated to the surface, and r_u x r_v with it. With differences a collapsed row contributes
// exactly nothing to the derivatives, and r is exactly the pole there.
namespace {

// Row i of the patch at t, its first and second v-derivatives: net[i][0] + sum_j B_j(t) (net[i][j] - net[i][0]).
struct RowSums {
    std::array<Point, 4> r;
    std::array<Eigen::Vector3d, 4> rv;
    std::array<Eigen::Vector3d, 4> rvv;
};

RowSums rowSums(const BezierNet& net, const Bernstein& bv) {
    RowSums rows;
    for (std::size_t i = 0; i < 4; ++i) {
        Eigen::Vector3d r = Eigen::Vector3d::Zero(), rv = Eigen::Vector3d::Zero(), rvv = Eigen::Vector3d::Zero();
        for (std::size_t j = 1; j < 4; ++j) {
            const Eigen::Vector3d delta = net[i][j] - net[i][0];
            r += bv.b[j] * delta;
            rv += bv.db[j] * delta;
            rvv += bv.ddb[j] * delta;
        }
        rows.r[i] = net[i][0] + r;
        rows.rv[i] = rv;
        rows.rvv[i] = rvv;
    }
    return rows;
}

// sum_i w[i] (x[i] - x[k]) + x[k], or without the "+ x[k]" for derivative weights, from the row k nearer s: at
// s = 0 or 1 the result is then exactly that end row (a pole).
template <class Vectors>
Eigen::Vector3d rowCombination(const std::array<double, 4>& w, const Vectors& x, double s, bool addReference) {
    const std::size_t k = s <= 0.5 ? 0 : 3;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < 4; ++i)
        if (i != k) sum += w[i] * (x[i] - x[k]);
    return addReference ? Eigen::Vector3d(x[k] + sum) : sum;
}

}  // namespace

Point BezierSurface::point(double u, double v) const {
    const auto [r, s] = locate(u, rows());
    const auto [c, t] = locate(v, columns());
    const RowSums rs = rowSums(patches_[r][c], bernstein(t));
    return rowCombination(bernstein(s).b, rs.r, s, true);
}

SurfaceJet BezierSurface::jet(double u, double v) const {
    const auto [r, s] = locate(u, rows());
    const auto [c, t] = locate(v, columns());
    const RowSums rs = rowSums(patches_[r][c], bernstein(t));
    const Bernstein bu = bernstein(s);
    SurfaceJet jet{rowCombination(bu.b, rs.r, s, true), rowCombination(bu.db, rs.r, s, false), Eigen::Vector3d::Zero()};
    for (std::size_t i = 0; i < 4; ++i) jet.rv += bu.b[i] * rs.rv[i];
    return jet;
}

SurfaceHessians BezierSurface::hessians(double u, double v) const {
    const auto [r, s] = locate(u, rows());
    const auto [c, t] = locate(v, columns());
    const RowSums rs = rowSums(patches_[r][c], bernstein(t));
    const Bernstein bu = bernstein(s);
    SurfaceHessians h{rowCombination(bu.ddb, rs.r, s, false), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (std::size_t i = 0; i < 4; ++i) {
        h.ruv += bu.db[i] * rs.rv[i];
        h.rvv += bu.b[i] * rs.rvv[i];
    }
    return h;
}

std::vector<PresetParameter> BezierSurface::presetParameters() const {
    PresetParameter p{"patches", {rows(), columns(), 4, 4, 3}, {}};
    p.values.reserve(rows() * columns() * 48);
    for (const auto& row : patches_)
        for (const BezierNet& net : row)
            for (const auto& netRow : net)
                for (const Point& q : netRow) p.values.insert(p.values.end(), {q.x(), q.y(), q.z()});
    return {p};
}

}  // namespace dropscope
