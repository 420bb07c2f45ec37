#include "geometry/parametric/ParametricRayIntersection.hpp"

#include "geometry/parametric/ParametricShapeTolerance.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace dropscope {

namespace tp = tolerance::parametric;

namespace {

struct NewtonSeed {
    double u;
    double v;
    double s;
    bool hasS;
};

// The part of the parameter domain Newton may roam while working on one cell.
struct Region {
    double u0, u1, v0, v1;
    bool u0Edge, u1Edge, v0Edge, v1Edge;  // the side is a non-periodic edge of the domain (e.g. a pole)
};

class RaySearch {
public:
    RaySearch(const ParametricBase& base, const AffineTransform& transform, const Point& p, const Eigen::Vector3d& d,
              double sMin, double band)
        : base_(base), transform_(transform), sMin_(sMin), band_(band) {
        pBase_ = transform.applyInverse(p);
        dBase_ = transform.applyInverseToVector(d);
        dBaseUnit_ = dBase_.normalized();
        accept_ = tp::kRootResidualBands * band +
                  tp::kRayRoundingUlps * (p.cwiseAbs().maxCoeff() + transform.translation().cwiseAbs().maxCoeff());
    }

    std::vector<RayCrossing> run() {
        const std::vector<CellNode>& nodes = base_.nodes();
        std::vector<std::int32_t> stack;
        if (meets(nodes.front().patch)) stack.push_back(0);
        while (!stack.empty()) {
            const CellNode& node = nodes[static_cast<std::size_t>(stack.back())];
            stack.pop_back();
            if (node.isLeaf()) {
                processCell(node.patch, node.curvature, 0);
                continue;
            }
            for (std::int32_t k = 0; k < node.childCount; ++k) {
                const std::int32_t child = node.firstChild + k;
                if (meets(nodes[static_cast<std::size_t>(child)].patch)) stack.push_back(child);
            }
        }
        return merged();
    }

private:
    // Slab tests: does the ray's part with s >= sMin (less the duplicate margin) meet the patch's box and its slab
    // along the normal axis?
    bool meets(const CellPatch& patch) const {
        double lo = sMin_ - tp::kDuplicateRootBands * band_;
        double hi = std::numeric_limits<double>::infinity();
        if (std::isfinite(patch.slabLow)) {
            const double start = pBase_.dot(patch.normalAxis);
            const double rate = dBase_.dot(patch.normalAxis);
            if (rate == 0.0) {
                if (start < patch.slabLow || start > patch.slabHigh) return false;
            } else {
                const double ta = (patch.slabLow - start) / rate;
                const double tb = (patch.slabHigh - start) / rate;
                lo = std::max(lo, std::min(ta, tb));
                hi = std::min(hi, std::max(ta, tb));
                if (lo > hi) return false;
            }
        }
        const Eigen::AlignedBox3d& box = patch.box;
        for (int k = 0; k < 3; ++k) {
            if (dBase_[k] == 0.0) {
                if (pBase_[k] < box.min()[k] || pBase_[k] > box.max()[k]) return false;
                continue;
            }
            const double ta = (box.min()[k] - pBase_[k]) / dBase_[k];
            const double tb = (box.max()[k] - pBase_[k]) / dBase_[k];
            lo = std::max(lo, std::min(ta, tb));
            hi = std::min(hi, std::max(ta, tb));
            if (lo > hi) return false;
        }
        return true;
    }

    void processCell(const CellPatch& patch, const CurvatureBound& curvature, int depth) {
        const bool transverse = std::abs(dBaseUnit_.dot(patch.normalAxis)) > patch.normalSpreadSine;
        if (transverse || depth >= tp::kRayMaxRefinement) {
            bool found = false;
            for (const NewtonSeed& seed : seeds(patch, !transverse)) {
                if (newton(seed, patch.cell)) {
                    found = true;
                    if (transverse) break;
                }
            }
            if ((found && transverse) || depth >= tp::kRayMaxRefinement) return;
        }
        const auto [alongU, alongV] = splitDirections(patch.corners);
        const CellSplit parts = splitCell(patch.cell, alongU, alongV);
        for (int k = 0; k < parts.count; ++k) {
            const CellPatch child = describeSubCell(base_.surface(), parts.parts[static_cast<std::size_t>(k)],
                                                    curvature, base_.boxPadding());
            if (meets(child)) processCell(child, curvature, depth + 1);
        }
    }

    // Where the ray meets the cell's two corner triangles (Moller-Trumbore), mapped linearly to (u, v); else the
    // cell's centre.
    // At the refinement limit (a near-tangent ray: possibly two roots close together) the corners too.
    std::vector<NewtonSeed> seeds(const CellPatch& patch, bool corners) const {
        std::vector<NewtonSeed> result;
        const ParameterCell& c = patch.cell;
        const auto& q = patch.corners;
        const auto hit = [&](const Point& a, const Point& b, const Point& e, double& beta, double& gamma, double& s) {
            const Eigen::Vector3d ab = b - a, ae = e - a;
            const Eigen::Vector3d h = dBase_.cross(ae);
            const double det = ab.dot(h);
            if (!(std::abs(det) > 0.0)) return false;
            const Eigen::Vector3d t = pBase_ - a;
            beta = t.dot(h) / det;
            const Eigen::Vector3d qv = t.cross(ab);
            gamma = dBase_.dot(qv) / det;
            s = ae.dot(qv) / det;
            return beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0;
        };
        double beta = 0.0, gamma = 0.0, s = 0.0;
        if (hit(q[0], q[1], q[2], beta, gamma, s))  // (u0,v0), (u1,v0), (u1,v1)
            result.push_back({c.u0 + (beta + gamma) * c.width(), c.v0 + gamma * c.height(), s, true});
        if (hit(q[0], q[2], q[3], beta, gamma, s))  // (u0,v0), (u1,v1), (u0,v1)
            result.push_back({c.u0 + beta * c.width(), c.v0 + (beta + gamma) * c.height(), s, true});
        if (result.empty() || corners) result.push_back({c.uMid(), c.vMid(), 0.0, false});
        if (corners) {
            result.push_back({c.u0, c.v0, 0.0, false});
            result.push_back({c.u1, c.v0, 0.0, false});
            result.push_back({c.u1, c.v1, 0.0, false});
            result.push_back({c.u0, c.v1, 0.0, false});
        }
        return result;
    }

    Region regionAround(const ParameterCell& cell) const {
        const ParameterDomain& dom = base_.domain();
        const double mu = tp::kNewtonRegionMargin * cell.width();
        const double mv = tp::kNewtonRegionMargin * cell.height();
        Region r{cell.u0 - mu, cell.u1 + mu, cell.v0 - mv, cell.v1 + mv, false, false, false, false};
        if (!base_.surface().periodicInU()) {
            if (r.u0 <= dom.u0) r = {dom.u0, r.u1, r.v0, r.v1, true, r.u1Edge, r.v0Edge, r.v1Edge};
            if (r.u1 >= dom.u1) r = {r.u0, dom.u1, r.v0, r.v1, r.u0Edge, true, r.v0Edge, r.v1Edge};
        }
        if (!base_.surface().periodicInV()) {
            if (r.v0 <= dom.v0) r = {r.u0, r.u1, dom.v0, r.v1, r.u0Edge, r.u1Edge, true, r.v1Edge};
            if (r.v1 >= dom.v1) r = {r.u0, r.u1, r.v0, dom.v1, r.u0Edge, r.u1Edge, r.v0Edge, true};
        }
        return r;
    }

    // Seed 000 eqs. 1.76, 1.77 in the base frame; records the root and returns true when it converges inside the
    // cell's region.
    bool newton(const NewtonSeed& seed, const ParameterCell& cell) {
        const Region region = regionAround(cell);
        double u = std::clamp(seed.u, region.u0, region.u1);
        double v = std::clamp(seed.v, region.v0, region.v1);
        double s = seed.s;
        bool haveS = seed.hasS;
        int limited = 0;
        // Once |F| is within the band, a few more steps polish s while they still reduce |F|: near tangency s
        // carries |F| / |cos| of error.
        bool converged = false;
        int polished = 0;
        struct {
            double u, v, s, residual;
            SurfaceJet jet;
        } best{};
        const auto recordBest = [&] { return record(best.u, best.v, best.s, best.jet); };
        for (int iteration = 0; iteration < tp::kNewtonMaxIterations; ++iteration) {
            const SurfaceJet jet = base_.jet(u, v);
            if (!haveS) {
                s = (jet.r - pBase_).dot(dBase_) / dBase_.squaredNorm();
                haveS = true;
            }
            const Eigen::Vector3d f = pBase_ + dBase_ * s - jet.r;
            const double residual = transform_.applyToVector(f).norm();  // |F| of eq. 1.76, length units
            if (converged) {
                if (!(residual < best.residual)) return recordBest();
                best = {u, v, s, residual, jet};
                if (++polished >= tp::kNewtonPolishSteps || residual == 0.0) return recordBest();
            } else if (residual <= accept_) {
                converged = true;
                best = {u, v, s, residual, jet};
            }
            Eigen::Matrix3d jacobian;
            jacobian.col(0) = -jet.ru;
            jacobian.col(1) = -jet.rv;
            jacobian.col(2) = dBase_;
            const double det = jacobian.determinant();
            if (!(std::abs(det) > tp::kNewtonSingularRatio * jet.ru.norm() * jet.rv.norm() * dBase_.norm())) {
                if (converged) return recordBest();
                // Singular (a pole, or tangent): nudge towards the cell's centre and go on.
                u += tp::kNewtonSingularNudge * (cell.uMid() - u);
                v += tp::kNewtonSingularNudge * (cell.vMid() - v);
                if (++limited > tp::kNewtonMaxLimitedAtEdge) return false;
                continue;
            }
            const Eigen::Vector3d step = -(jacobian.inverse() * f);
            // Keep (u, v) in the region: a step that would leave it goes half-way to its boundary.
            double t = 1.0;
            bool atEdge = false;
            const auto limit = [&](double x, double dx, double lo, double hi, bool loEdge, bool hiEdge) {
                if (x + dx < lo && dx < 0.0) {
                    const double tb = 0.5 * (lo - x) / dx;
                    if (tb < t) {
                        t = tb;
                        atEdge = loEdge;
                    }
                } else if (x + dx > hi && dx > 0.0) {
                    const double tb = 0.5 * (hi - x) / dx;
                    if (tb < t) {
                        t = tb;
                        atEdge = hiEdge;
                    }
                }
            };
            limit(u, step[0], region.u0, region.u1, region.u0Edge, region.u1Edge);
            limit(v, step[1], region.v0, region.v1, region.v0Edge, region.v1Edge);
            if (t < 1.0) {
                if (converged) return recordBest();
                ++limited;
                if (limited > (atEdge ? tp::kNewtonMaxLimitedAtEdge : tp::kNewtonMaxLimited)) return false;
            } else {
                limited = 0;
            }
            u += t * step[0];
            v += t * step[1];
            s += t * step[2];
            if (!std::isfinite(u) || !std::isfinite(v) || !std::isfinite(s)) return converged && recordBest();
        }
        return converged && recordBest();
    }

    bool record(double u, double v, double s, const SurfaceJet& jet) {
        const Eigen::Vector2d folded = base_.wrap(u, v);
        RayCrossing crossing;
        crossing.s = s;
        crossing.u = folded.x();
        crossing.v = folded.y();
        crossing.degenerate = isDegenerate(jet);
        // Eq. 1.71, outward; at a degenerate point (a ray through a pole) r_u x r_v is 0 or noise: the base's normal
        // there (the pole's) instead.
        Eigen::Vector3d normal = base_.orientation() * jet.ru.cross(jet.rv);
        if (crossing.degenerate) {
            const Direction n = base_.outwardNormal(u, v);
            normal = n ? n.vector() : Eigen::Vector3d::Zero();
        }
        // In the placed frame the normal is M^-T n and d . M^-T n = (M^-1 d) . n = d' . n.
        const double placedNorm = (transform_.inverseMatrix().transpose() * normal).norm();
        crossing.cosine = placedNorm > 0.0 ? dBase_.dot(normal) / placedNorm : 0.0;
        roots_.push_back(crossing);
        return true;
    }

    std::vector<RayCrossing> merged() {
        std::sort(roots_.begin(), roots_.end(), [](const RayCrossing& a, const RayCrossing& b) { return a.s < b.s; });
        std::vector<RayCrossing> result;
        const double duplicate = tp::kDuplicateRootBands * band_;
        bool lastWasTouch = false;
        double touchS = 0.0;
        for (const RayCrossing& c : roots_) {
            if (lastWasTouch && c.s - touchS <= duplicate) continue;  // a third copy of a dropped touch
            lastWasTouch = false;
            if (!result.empty() && c.s - result.back().s <= duplicate) {
                const RayCrossing& previous = result.back();
                const bool sameWay = c.degenerate || previous.degenerate || (c.cosine > 0.0) == (previous.cosine > 0.0);
                if (!sameWay) {  // in and out within the band: a touch, not a crossing
                    touchS = c.s;
                    lastWasTouch = true;
                    result.pop_back();
                }
                continue;
            }
            result.push_back(c);
        }
        std::erase_if(result, [&](const RayCrossing& c) { return c.s < sMin_; });
        return result;
    }

    const ParametricBase& base_;
    const AffineTransform& transform_;
    Point pBase_;
    Eigen::Vector3d dBase_;
    Eigen::Vector3d dBaseUnit_;
    double sMin_;
    double band_;
    double accept_;
    std::vector<RayCrossing> roots_;
};

}  // namespace

std::vector<RayCrossing> findRayCrossings(const ParametricBase& base, const AffineTransform& transform, const Point& p,
                                          const Eigen::Vector3d& d, double sMin, double band) {
    if (!p.allFinite() || !d.allFinite()) return {};
    return RaySearch(base, transform, p, d, sMin, band).run();
}

}  // namespace dropscope
