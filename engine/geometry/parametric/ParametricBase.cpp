#include "geometry/parametric/ParametricBase.hpp"

#include "geometry/parametric/ParametricShapeTolerance.hpp"
#include "geometry/parametric/SurfaceIntegrals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace dropscope {

namespace tp = tolerance::parametric;

namespace {

constexpr int kSamples = tp::kCellSamples;

// Sample k of kSamples along [lo, hi], the last one exactly hi.
double samplePosition(double lo, double hi, int k) {
    return k == kSamples - 1 ? hi : lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(kSamples - 1);
}

double foldPeriodic(double x, double lo, double hi) {
    const double period = hi - lo;
    if (x >= lo && x < hi) return x;
    double y = std::fmod(x - lo, period);
    if (y < 0.0) y += period;
    return lo + y;
}

// Average length of the curves along one parameter (the other fixed at a few values): how finely the mesh
// must divide that parameter.
double averageCurveLength(const ParametricSurface& surface, bool alongU) {
    constexpr int kCurves = 5;
    constexpr int kSegments = 32;
    const ParameterDomain d = surface.domain();
    double total = 0.0;
    for (int c = 0; c < kCurves; ++c) {
        const double fixedFraction = (static_cast<double>(c) + 0.5) / kCurves;
        Point previous;
        for (int k = 0; k <= kSegments; ++k) {
            const double t = static_cast<double>(k) / kSegments;
            const Point r = alongU ? surface.point(d.u0 + t * (d.u1 - d.u0), d.v0 + fixedFraction * (d.v1 - d.v0))
                                   : surface.point(d.u0 + fixedFraction * (d.u1 - d.u0), d.v0 + t * (d.v1 - d.v0));
            if (k > 0) total += (r - previous).norm();
            previous = r;
        }
    }
    return total / kCurves;
}

}  // namespace

CellSplit splitCell(const ParameterCell& cell, bool alongU, bool alongV) {
    const double um = cell.uMid();
    const double vm = cell.vMid();
    const double u0 = cell.u0, u1 = cell.u1, v0 = cell.v0, v1 = cell.v1;
    if (alongU && alongV)
        return {{ParameterCell{u0, um, v0, vm}, ParameterCell{um, u1, v0, vm}, ParameterCell{u0, um, vm, v1},
                 ParameterCell{um, u1, vm, v1}},
                4};
    if (alongU) return {{ParameterCell{u0, um, v0, v1}, ParameterCell{um, u1, v0, v1}}, 2};
    return {{ParameterCell{u0, u1, v0, vm}, ParameterCell{u0, u1, vm, v1}}, 2};
}

std::pair<bool, bool> splitDirections(const std::array<Point, 4>& corners) {
    // corners: (u0, v0), (u1, v0), (u1, v1), (u0, v1)
    const double lengthU = std::max((corners[1] - corners[0]).norm(), (corners[2] - corners[3]).norm());
    const double lengthV = std::max((corners[3] - corners[0]).norm(), (corners[2] - corners[1]).norm());
    const double longest = std::max(lengthU, lengthV);
    if (!(longest > 0.0)) return {true, true};
    return {lengthU >= tp::kSplitLengthRatio * longest, lengthV >= tp::kSplitLengthRatio * longest};
}

bool isDegenerate(const SurfaceJet& jet) {
    return !(jet.ru.cross(jet.rv).norm() > tp::kDegenerateRatio * jet.ru.norm() * jet.rv.norm());
}

CurvatureBound sampleCurvature(const ParametricSurface& surface, const ParameterCell& cell) {
    CurvatureBound bound;
    for (int i = 0; i < kSamples; ++i) {
        for (int j = 0; j < kSamples; ++j) {
            const SurfaceHessians h =
                surface.hessians(samplePosition(cell.u0, cell.u1, i), samplePosition(cell.v0, cell.v1, j));
            if (!h.ruu.allFinite() || !h.ruv.allFinite() || !h.rvv.allFinite()) continue;
            bound.uu = bound.uu.cwiseMax(h.ruu.cwiseAbs());
            bound.uv = bound.uv.cwiseMax(h.ruv.cwiseAbs());
            bound.vv = bound.vv.cwiseMax(h.rvv.cwiseAbs());
        }
    }
    bound.uu *= tp::kCurvatureSafety;
    bound.uv *= tp::kCurvatureSafety;
    bound.vv *= tp::kCurvatureSafety;
    return bound;
}

namespace {

template <int N>
CellPatch describeCellOn(const ParametricSurface& surface, const ParameterCell& cell, const CurvatureBound& curvature,
                         double padding) {
    const auto position = [](double lo, double hi, int k) {
        return k == N - 1 ? hi : lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(N - 1);
    };
    std::array<Point, N * N> points;
    std::array<Eigen::Vector3d, N * N> normals;
    std::array<bool, N * N> regular{};
    for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
            const auto k = static_cast<std::size_t>(i * N + j);
            const SurfaceJet jet = surface.jet(position(cell.u0, cell.u1, i), position(cell.v0, cell.v1, j));
            points[k] = jet.r;
            regular[k] = !isDegenerate(jet);
            if (regular[k]) normals[k] = jet.ru.cross(jet.rv).normalized();
        }
    }
    const auto at = [&](int i, int j) -> const Point& { return points[static_cast<std::size_t>(i * N + j)]; };

    CellPatch patch;
    patch.cell = cell;
    for (const Point& p : points) patch.box.extend(p);

    // How far the surface can stray from the samples: the curvature bound at the sample spacing, and at least
    // a multiple of the deviation measured at twice that spacing (ParametricShapeTolerance.hpp).
    const double gu = cell.width() / (N - 1);
    const double gv = cell.height() / (N - 1);
    const Eigen::Vector3d curvaturePad =
        (gu * gu * curvature.uu + 2.0 * gu * gv * curvature.uv + gv * gv * curvature.vv) / 8.0;
    Eigen::Vector3d measured = Eigen::Vector3d::Zero();
    for (int i = 1; i < N - 1; ++i) {
        for (int j = 0; j < N; ++j) {
            measured = measured.cwiseMax((at(i, j) - 0.5 * (at(i - 1, j) + at(i + 1, j))).cwiseAbs());
            measured = measured.cwiseMax((at(j, i) - 0.5 * (at(j, i - 1) + at(j, i + 1))).cwiseAbs());
        }
    }
    const Eigen::Vector3d pad =
        curvaturePad.cwiseMax(tp::kMeasuredDeviationSafety * measured) + Eigen::Vector3d::Constant(padding);
    patch.box.min() -= pad;
    patch.box.max() += pad;

    patch.corners = {at(0, 0), at(N - 1, 0), at(N - 1, N - 1), at(0, N - 1)};

    // The normal cone: around the centre's normal (or the mean where the centre is degenerate).
    const auto center = static_cast<std::size_t>((N / 2) * N + N / 2);
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    if (regular[center]) {
        axis = normals[center];
    } else {
        for (std::size_t k = 0; k < normals.size(); ++k)
            if (regular[k]) axis += normals[k];
    }
    if (axis.norm() > 0.0) {
        axis.normalize();
        double leastCosine = 1.0;
        for (std::size_t k = 0; k < normals.size(); ++k)
            if (regular[k]) leastCosine = std::min(leastCosine, normals[k].dot(axis));
        const double halfAngle = tp::kNormalSpreadSafety * std::acos(std::clamp(leastCosine, -1.0, 1.0));
        patch.normalAxis = axis;
        patch.normalSpreadSine = halfAngle >= 0.5 * std::numbers::pi ? 1.0 : std::sin(halfAngle);
        // The slab along the axis that holds the patch: its samples' extent, padded like the box.
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (const Point& p : points) {
            lo = std::min(lo, p.dot(axis));
            hi = std::max(hi, p.dot(axis));
        }
        const double axisPad = pad.dot(axis.cwiseAbs());
        patch.slabLow = lo - axisPad;
        patch.slabHigh = hi + axisPad;
    }
    return patch;
}

}  // namespace

CellPatch describeCell(const ParametricSurface& surface, const ParameterCell& cell, const CurvatureBound& curvature,
                       double padding) {
    return describeCellOn<tp::kCellSamples>(surface, cell, curvature, padding);
}

CellPatch describeSubCell(const ParametricSurface& surface, const ParameterCell& cell, const CurvatureBound& curvature,
                          double padding) {
    return describeCellOn<tp::kSubCellSamples>(surface, cell, curvature, padding);
}

ParametricBase::ParametricBase(std::shared_ptr<const ParametricSurface> surface) : surface_(std::move(surface)) {
    if (!surface_) throw std::invalid_argument("parametric surface must not be null");
    domain_ = surface_->domain();
    const double length = surface_->characteristicLength();
    boxPadding_ = tp::kBoxPaddingRelative * length;

    signedVolume_ = signedVolumeIntegral(*surface_, tp::kIntegralRelative).value;
    if (!(std::abs(signedVolume_) > tp::kMinVolumeRelative * length * length * length))
        throw std::invalid_argument("parametric surface encloses no volume (signed volume " +
                                    std::to_string(signedVolume_) + ")");
    orientation_ = signedVolume_ > 0.0 ? 1.0 : -1.0;
    area_ = surfaceAreaIntegral(*surface_, Eigen::Matrix3d::Identity(), tp::kIntegralRelative).value;
    for (int k = 0; k < 3; ++k)
        extremes_[static_cast<std::size_t>(k)] = extremeRange(*surface_, Eigen::Vector3d::Unit(k));

    poleAtU0_ = !surface_->periodicInU() && collapsedEdge(true, domain_.u0);
    poleAtU1_ = !surface_->periodicInU() && collapsedEdge(true, domain_.u1);
    poleAtV0_ = !surface_->periodicInV() && collapsedEdge(false, domain_.v0);
    poleAtV1_ = !surface_->periodicInV() && collapsedEdge(false, domain_.v1);
    nodes_.resize(1);
    buildNode(0, ParameterCell{domain_.u0, domain_.u1, domain_.v0, domain_.v1}, 0);
    for (const CellNode& node : nodes_)
        if (node.isLeaf()) cover_.push_back(node.patch.box);
    buildMesh();
}

std::int32_t ParametricBase::buildNode(std::size_t slot, const ParameterCell& cell, int depth) {
    CellNode node;
    node.curvature = sampleCurvature(*surface_, cell);
    node.patch = describeCell(*surface_, cell, node.curvature, boxPadding_);
    const double leafSize = tp::kLeafSizeRelative * surface_->characteristicLength();
    const bool split = depth < tp::kLeafMaxDepth &&
                       (depth < tp::kLeafMinDepth ||
                        node.patch.normalSpreadSine > std::sin(tp::kNormalSpreadSafety * tp::kLeafNormalSpread) ||
                        node.patch.box.diagonal().norm() > leafSize);
    if (split) {
        // At the minimum depth always into quarters, so that the top of the tree is balanced.
        const auto [alongU, alongV] =
            depth < tp::kLeafMinDepth ? std::pair{true, true} : splitDirections(node.patch.corners);
        const CellSplit parts = splitCell(cell, alongU, alongV);
        const std::size_t count = static_cast<std::size_t>(parts.count);
        const std::size_t first = nodes_.size();
        nodes_.resize(first + count);
        node.firstChild = static_cast<std::int32_t>(first);
        node.childCount = parts.count;
        for (std::size_t k = 0; k < count; ++k) buildNode(first + k, parts.parts[k], depth + 1);
        // Inner nodes: the union of the children (tighter than the node's own samples allow).
        node.patch.box.setEmpty();
        for (std::size_t k = 0; k < count; ++k) node.patch.box.extend(nodes_[first + k].patch.box);
        node.patch.slabLow = -std::numeric_limits<double>::infinity();
        node.patch.slabHigh = std::numeric_limits<double>::infinity();
    }
    nodes_[slot] = node;
    return static_cast<std::int32_t>(slot);
}

Eigen::Vector2d ParametricBase::wrap(double u, double v) const {
    const double wu =
        surface_->periodicInU() ? foldPeriodic(u, domain_.u0, domain_.u1) : std::clamp(u, domain_.u0, domain_.u1);
    const double wv =
        surface_->periodicInV() ? foldPeriodic(v, domain_.v0, domain_.v1) : std::clamp(v, domain_.v0, domain_.v1);
    return {wu, wv};
}

SurfaceJet ParametricBase::jet(double u, double v) const {
    const Eigen::Vector2d w = wrap(u, v);
    return surface_->jet(w.x(), w.y());
}

bool ParametricBase::collapsedEdge(bool uEdge, double value) const {
    const ParametricSurface& s = *surface_;
    constexpr int kProbes = 8;
    const double tolerance = tp::kMeshCollapsedRelative * s.characteristicLength();
    const Point first = uEdge ? s.point(value, domain_.v0) : s.point(domain_.u0, value);
    for (int k = 1; k <= kProbes; ++k) {
        const double t = static_cast<double>(k) / kProbes;
        const Point q = uEdge ? s.point(value, domain_.v0 + t * (domain_.v1 - domain_.v0))
                              : s.point(domain_.u0 + t * (domain_.u1 - domain_.u0), value);
        if (!((q - first).norm() <= tolerance)) return false;
    }
    return true;
}

Direction ParametricBase::outwardNormal(double u, double v) const {
    const Eigen::Vector2d w = wrap(u, v);
    // Seed 000 eq. 1.71 is 0/0 at a pole (a whole edge of the domain collapsed to one point): the normal is the mean
    // of the normals on a tiny ring just inside that edge, where their first-order tilts cancel. This is decided
    // before looking at r_u x r_v there: at a pole it is zero only up to how the surface rounds r_v (a Bezier row
    // summed over a collapsed edge leaves ~eps |r| along r itself), and such noise passes the degeneracy test,
    // which is relative to |r_u| |r_v|.
    const auto ringNormal = [&](bool uEdge, double edge, double inward) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (int k = 0; k < tp::kPoleRingSamples; ++k) {
            const double t = (static_cast<double>(k) + 0.5) / tp::kPoleRingSamples;
            const SurfaceJet r = uEdge ? surface_->jet(edge + inward * tp::kPoleRingStep * (domain_.u1 - domain_.u0),
                                                       domain_.v0 + t * (domain_.v1 - domain_.v0))
                                       : surface_->jet(domain_.u0 + t * (domain_.u1 - domain_.u0),
                                                       edge + inward * tp::kPoleRingStep * (domain_.v1 - domain_.v0));
            if (!isDegenerate(r)) sum += r.ru.cross(r.rv).normalized();
        }
        return Direction(orientation_ * sum);
    };
    if (w.x() == domain_.u0 && poleAtU0_) return ringNormal(true, domain_.u0, 1.0);
    if (w.x() == domain_.u1 && poleAtU1_) return ringNormal(true, domain_.u1, -1.0);
    if (w.y() == domain_.v0 && poleAtV0_) return ringNormal(false, domain_.v0, 1.0);
    if (w.y() == domain_.v1 && poleAtV1_) return ringNormal(false, domain_.v1, -1.0);

    SurfaceJet j = surface_->jet(w.x(), w.y());
    if (!isDegenerate(j)) return Direction(orientation_ * j.ru.cross(j.rv));  // seed 000 eq. 1.71, outward

    // Elsewhere: a tiny step inside the domain, towards its centre.
    const double uCenter = 0.5 * (domain_.u0 + domain_.u1);
    const double vCenter = 0.5 * (domain_.v0 + domain_.v1);
    const double su = w.x() <= uCenter ? 1.0 : -1.0;
    const double sv = w.y() <= vCenter ? 1.0 : -1.0;
    double step = tp::kDegenerateStep;
    for (int k = 0; k < tp::kDegenerateStepTries && isDegenerate(j); ++k, step *= 10.0) {
        j = surface_->jet(w.x() + su * step * (domain_.u1 - domain_.u0), w.y() + sv * step * (domain_.v1 - domain_.v0));
    }
    if (isDegenerate(j)) return Direction::invalid();
    return Direction(orientation_ * j.ru.cross(j.rv));
}

void ParametricBase::buildMesh() {
    const ParametricSurface& s = *surface_;
    const double lengthU = std::max(averageCurveLength(s, true), std::numeric_limits<double>::min());
    const double lengthV = std::max(averageCurveLength(s, false), std::numeric_limits<double>::min());
    const double quads = static_cast<double>(tp::kMeshQuads);
    const int nu = std::max(tp::kMeshMinDivisions, static_cast<int>(std::lround(std::sqrt(quads * lengthU / lengthV))));
    const int nv = std::max(tp::kMeshMinDivisions, static_cast<int>(std::lround(quads / nu)));
    const bool pu = s.periodicInU();
    const bool pv = s.periodicInV();
    // Along a periodic parameter the last column is the first one again: the seam shares its vertices.
    const int rows = pu ? nu : nu + 1;
    const int columns = pv ? nv : nv + 1;

    mesh_.vertices.reserve(static_cast<std::size_t>(rows * columns));
    mesh_.normals.reserve(static_cast<std::size_t>(rows * columns));
    for (int i = 0; i < rows; ++i) {
        const double u = i == nu ? domain_.u1 : domain_.u0 + (domain_.u1 - domain_.u0) * i / static_cast<double>(nu);
        for (int j = 0; j < columns; ++j) {
            const double v =
                j == nv ? domain_.v1 : domain_.v0 + (domain_.v1 - domain_.v0) * j / static_cast<double>(nv);
            mesh_.vertices.push_back(s.point(u, v));
            const Direction n = outwardNormal(u, v);
            mesh_.normals.push_back(n ? n.vector() : Eigen::Vector3d::UnitZ());
        }
    }
    const auto index = [&](int i, int j) { return static_cast<std::uint32_t>((i % rows) * columns + (j % columns)); };
    const double collapsed = tp::kMeshCollapsedRelative * s.characteristicLength();
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const Point& pa = mesh_.vertices[a];
        const Point& pb = mesh_.vertices[b];
        const Point& pc = mesh_.vertices[c];
        if ((pa - pb).norm() <= collapsed || (pb - pc).norm() <= collapsed || (pc - pa).norm() <= collapsed) return;
        // Counter-clockwise seen from outside: (b - a) x (c - a) ~ r_u x r_v, outward when orientation > 0.
        if (orientation_ > 0.0)
            mesh_.triangles.push_back({a, b, c});
        else
            mesh_.triangles.push_back({a, c, b});
    };
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            emit(a, b, c);
            emit(a, c, d);
        }
    }
}

std::shared_ptr<const ParametricBase> makeParametricBase(std::shared_ptr<const ParametricSurface> surface) {
    return std::make_shared<const ParametricBase>(std::move(surface));
}

}  // namespace dropscope
