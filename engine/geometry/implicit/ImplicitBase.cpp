#include "geometry/implicit/ImplicitBase.hpp"

#include "geometry/Tolerance.hpp"
#include "geometry/implicit/ConvexBody.hpp"
#include "geometry/implicit/ImplicitTolerance.hpp"
#include "geometry/implicit/RayRootFinder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace dropscope {

namespace {

using tolerance::implicit::kMinStepBands;
using tolerance::implicit::kRefineBands;

// ---- Marching tetrahedra -------------------------------------------------------------------------

class TetrahedronMesher {
public:
    TetrahedronMesher(const ImplicitFunction& f, const Eigen::AlignedBox3d& bounds, double band, int cells)
        : f_(f),
          n_(cells),
          origin_(bounds.min()),
          step_(bounds.sizes() / static_cast<double>(cells)),
          refineBand_(kRefineBands * band) {
        const std::size_t nodes =
            static_cast<std::size_t>(n_ + 1) * static_cast<std::size_t>(n_ + 1) * static_cast<std::size_t>(n_ + 1);
        values_.resize(nodes);
        for (int k = 0; k <= n_; ++k)
            for (int j = 0; j <= n_; ++j)
                for (int i = 0; i <= n_; ++i) values_[index(i, j, k)] = f_.value(node(i, j, k));
    }

    SurfaceMesh run() {
        // The Kuhn (Freudenthal) split: the 6 tetrahedra of a cube are the monotone paths from corner
        // (0,0,0) to (1,1,1), one axis at a time in each of the 6 orders. Every cube uses the same split,
        // so the face diagonals of neighbouring cubes match and the mesh is closed.
        static constexpr std::array<std::array<int, 3>, 6> kOrders{
            {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
        for (int k = 0; k < n_; ++k)
            for (int j = 0; j < n_; ++j)
                for (int i = 0; i < n_; ++i)
                    for (const auto& order : kOrders) {
                        std::array<int, 3> corner{i, j, k};
                        std::array<std::size_t, 4> tet{};
                        tet[0] = index(corner[0], corner[1], corner[2]);
                        for (int s = 0; s < 3; ++s) {
                            ++corner[static_cast<std::size_t>(order[static_cast<std::size_t>(s)])];
                            tet[static_cast<std::size_t>(s) + 1] = index(corner[0], corner[1], corner[2]);
                        }
                        tetrahedron(tet);
                    }
        return std::move(mesh_);
    }

private:
    std::size_t index(int i, int j, int k) const {
        const auto n = static_cast<std::size_t>(n_ + 1);
        return (static_cast<std::size_t>(k) * n + static_cast<std::size_t>(j)) * n + static_cast<std::size_t>(i);
    }
    Point nodeAt(std::size_t idx) const {
        const auto n = static_cast<std::size_t>(n_ + 1);
        return node(static_cast<int>(idx % n), static_cast<int>((idx / n) % n), static_cast<int>(idx / (n * n)));
    }
    Point node(int i, int j, int k) const { return origin_ + Eigen::Vector3d(i, j, k).cwiseProduct(step_); }

    // The mesh vertex on edge (a, b), a inside and b outside: one per edge, shared by its tetrahedra.
    std::uint32_t edgeVertex(std::size_t a, std::size_t b) {
        const std::uint64_t key = static_cast<std::uint64_t>(std::min(a, b)) * values_.size() + std::max(a, b);
        const auto found = edges_.find(key);
        if (found != edges_.end()) return found->second;
        const Point pa = nodeAt(a);
        const Eigen::Vector3d edge = nodeAt(b) - pa;
        const RayCrossing crossing =
            refineCrossing(f_, pa, edge, 0.0, values_[a], 1.0, values_[b], refineBand_ / edge.norm());
        const Point vertex = pa + crossing.t * edge;
        const auto id = static_cast<std::uint32_t>(mesh_.vertices.size());
        mesh_.vertices.push_back(vertex);
        Eigen::Vector3d normal = f_.gradient(vertex);
        normal = normal.norm() > 0.0 ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d(edge.normalized());
        mesh_.normals.push_back(normal);
        edges_.emplace(key, id);
        return id;
    }

    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Eigen::Vector3d& outward) {
        if (a == b || b == c || a == c) return;
        const Eigen::Vector3d& pa = mesh_.vertices[a];
        const Eigen::Vector3d normal = (mesh_.vertices[b] - pa).cross(mesh_.vertices[c] - pa);
        if (normal.squaredNorm() == 0.0) return;  // a vertex sitting on a grid node: degenerate sliver
        if (normal.dot(outward) >= 0.0) {
            mesh_.triangles.push_back({a, b, c});
        } else {
            mesh_.triangles.push_back({a, c, b});
        }
    }

    // The 16 sign cases of one tetrahedron: 0 or 4 corners inside give nothing, 1 or 3 a triangle,
    // 2 a quadrilateral (two triangles). Counter-clockwise from outside: each triangle's normal is
    // turned towards the outside corners, away from the inside ones.
    void tetrahedron(const std::array<std::size_t, 4>& tet) {
        std::array<std::size_t, 4> in{};
        std::array<std::size_t, 4> out{};
        std::size_t nIn = 0;
        std::size_t nOut = 0;
        Eigen::Vector3d inSum = Eigen::Vector3d::Zero();
        Eigen::Vector3d outSum = Eigen::Vector3d::Zero();
        for (std::size_t corner : tet) {
            if (values_[corner] < 0.0) {
                in[nIn++] = corner;
                inSum += nodeAt(corner);
            } else {
                out[nOut++] = corner;
                outSum += nodeAt(corner);
            }
        }
        if (nIn == 0 || nOut == 0) return;
        const Eigen::Vector3d outward = outSum / static_cast<double>(nOut) - inSum / static_cast<double>(nIn);
        if (nIn == 1) {
            addTriangle(edgeVertex(in[0], out[0]), edgeVertex(in[0], out[1]), edgeVertex(in[0], out[2]), outward);
        } else if (nOut == 1) {
            addTriangle(edgeVertex(in[0], out[0]), edgeVertex(in[1], out[0]), edgeVertex(in[2], out[0]), outward);
        } else {
            // Cyclic order around the quadrilateral: consecutive vertices share a corner.
            const std::uint32_t q0 = edgeVertex(in[0], out[0]);
            const std::uint32_t q1 = edgeVertex(in[0], out[1]);
            const std::uint32_t q2 = edgeVertex(in[1], out[1]);
            const std::uint32_t q3 = edgeVertex(in[1], out[0]);
            addTriangle(q0, q1, q2, outward);
            addTriangle(q0, q2, q3, outward);
        }
    }

    const ImplicitFunction& f_;
    int n_;
    Point origin_;
    Eigen::Vector3d step_;
    double refineBand_;
    std::vector<double> values_;
    std::unordered_map<std::uint64_t, std::uint32_t> edges_;
    SurfaceMesh mesh_;
};

// ---- Surface cover ------------------------------------------------------------------------------

// Whether a box may hold a surface point: at a surface point r, |f(centre)| = |f(centre) - f(r)| <=
// L |centre - r| <= L * half-diagonal.
bool mayHoldSurface(const ImplicitFunction& f, const Eigen::AlignedBox3d& box) {
    return std::abs(f.value(box.center())) <= f.lipschitzBound() * 0.5 * box.diagonal().norm();
}

std::array<Eigen::AlignedBox3d, 8> octants(const Eigen::AlignedBox3d& box) {
    std::array<Eigen::AlignedBox3d, 8> children;
    const Point center = box.center();
    for (std::size_t c = 0; c < 8; ++c) {
        const auto corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
        children[c] = Eigen::AlignedBox3d(center.cwiseMin(corner), center.cwiseMax(corner));
    }
    return children;
}

std::vector<Eigen::AlignedBox3d> lipschitzCover(const ImplicitFunction& f, const Eigen::AlignedBox3d& bounds) {
    std::vector<Eigen::AlignedBox3d> kept{bounds};
    for (int depth = 0;
         depth < tolerance::implicit::kCoverMaxDepth && kept.size() < tolerance::implicit::kCoverMinBoxes; ++depth) {
        std::vector<Eigen::AlignedBox3d> next;
        for (const Eigen::AlignedBox3d& box : kept)
            for (const Eigen::AlignedBox3d& child : octants(box))
                if (mayHoldSurface(f, child)) next.push_back(child);
        kept = std::move(next);
    }
    return kept;
}

// ---- Line integrals -----------------------------------------------------------------------------

struct LineSums {
    std::array<double, 3> volume{};  // one estimate per axis
    double area = 0.0;
};

LineSums sweep(const ImplicitFunction& f, const AffineTransform& transform, const Eigen::AlignedBox3d& baseBounds,
               const Eigen::AlignedBox3d& worldBounds, double band, int n) {
    LineSums sums;
    const Eigen::Vector3d size = worldBounds.sizes();
    for (int k = 0; k < 3; ++k) {
        const int u = (k + 1) % 3;
        const int v = (k + 2) % 3;
        const double du = size[u] / n;
        const double dv = size[v] / n;
        const Eigen::Vector3d direction = transform.applyInverseToVector(Eigen::Vector3d::Unit(k));
        double length = 0.0;
        double projected = 0.0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                Point world = worldBounds.min();
                world[u] += (i + 0.5) * du;
                world[v] += (j + 0.5) * dv;
                const Point origin = transform.applyInverse(world);
                const auto range = clipToBox(baseBounds, origin, direction);
                if (!range) continue;
                double entered = range->first;
                RayRootFinder finder(f, origin, direction, range->first, range->second, kMinStepBands * band,
                                     kRefineBands * band);
                while (const auto crossing = finder.next()) {
                    if (crossing->entering) {
                        entered = crossing->t;
                    } else {
                        length += crossing->t - entered;
                    }
                    const Eigen::Vector3d normal = transform.inverseMatrix().transpose() * crossing->gradient;
                    const double norm = normal.norm();
                    if (norm > 0.0) projected += std::abs(normal[k]) / norm;
                }
            }
        }
        sums.volume[static_cast<std::size_t>(k)] = length * du * dv;
        sums.area += projected * du * dv;
    }
    return sums;
}

}  // namespace

ImplicitBase::ImplicitBase(std::shared_ptr<const ImplicitFunction> function) : function_(std::move(function)) {
    if (!function_) throw std::invalid_argument("implicit function must not be null");
    const Eigen::AlignedBox3d raw = function_->bounds();
    const double padding = tolerance::implicit::kBoundsPaddingRelative * raw.diagonal().norm();
    bounds_ = Eigen::AlignedBox3d(raw.min().array() - padding, raw.max().array() + padding);
    band_ = tolerance::surfaceBand(function_->characteristicLength(), largestCoordinate(bounds_));
}

const SurfaceMesh& ImplicitBase::mesh() const {
    std::call_once(meshOnce_, [this] {
        mesh_ = TetrahedronMesher(*function_, bounds_, band_, tolerance::implicit::kMeshCells).run();
    });
    return mesh_;
}

const std::vector<Eigen::AlignedBox3d>& ImplicitBase::surfaceCover() const {
    std::call_once(coverOnce_, [this] { cover_ = lipschitzCover(*function_, bounds_); });
    return cover_;
}

const BodyIntegrals& ImplicitBase::integrals() const {
    std::call_once(integralsOnce_, [this] {
        if (const std::optional<Point> center = function_->convexCenter()) {
            integrals_ = convexBodyIntegrals(*function_, *center, bounds_, AffineTransform(), band_,
                                             tolerance::implicit::kConvexIntegralOrder);
        } else {
            integrals_ = bodyIntegrals(*function_, AffineTransform(), bounds_, bounds_, band_,
                                       tolerance::implicit::kIntegralLines);
        }
    });
    return integrals_;
}

BodyIntegrals bodyIntegrals(const ImplicitFunction& f, const AffineTransform& transform,
                            const Eigen::AlignedBox3d& baseBounds, const Eigen::AlignedBox3d& worldBounds, double band,
                            int lines) {
    const LineSums coarse = sweep(f, transform, baseBounds, worldBounds, band, lines);
    const LineSums fine = sweep(f, transform, baseBounds, worldBounds, band, 2 * lines);
    const auto mean = [](const std::array<double, 3>& v) { return (v[0] + v[1] + v[2]) / 3.0; };
    BodyIntegrals result;
    result.volume.value = mean(fine.volume);
    double spread = std::abs(result.volume.value - mean(coarse.volume));
    for (double perAxis : fine.volume) spread = std::max(spread, std::abs(perAxis - result.volume.value));
    result.volume.errorEstimate = tolerance::implicit::kIntegralSafety * spread;
    result.area.value = fine.area;
    result.area.errorEstimate = tolerance::implicit::kIntegralSafety * std::abs(fine.area - coarse.area);
    return result;
}

ExtremeBounds maximumOverBody(const ImplicitFunction& f, const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& ell,
                              double tolerance) {
    struct Cell {
        Eigen::AlignedBox3d box;
        double upper;
        bool operator<(const Cell& other) const { return upper < other.upper; }
    };
    const Eigen::Vector3d weight = ell.cwiseAbs();
    const auto upperOf = [&](const Eigen::AlignedBox3d& box) {
        return ell.dot(box.center()) + weight.dot(0.5 * box.sizes());
    };
    std::priority_queue<Cell> queue;
    queue.push({bounds, upperOf(bounds)});
    double lower = -std::numeric_limits<double>::infinity();
    std::size_t examined = 0;
    while (!queue.empty()) {
        const Cell cell = queue.top();
        // The largest upper bound left: no surface point (so no body point) lies above it.
        if (cell.upper - lower <= tolerance || examined >= tolerance::implicit::kExtremeMaxCells)
            return {lower, std::max(cell.upper, lower)};
        queue.pop();
        for (const Eigen::AlignedBox3d& child : octants(cell.box)) {
            ++examined;
            const Point center = child.center();
            const double value = f.value(center);
            if (std::abs(value) > f.lipschitzBound() * 0.5 * child.diagonal().norm()) continue;
            if (value <= 0.0) lower = std::max(lower, ell.dot(center));
            const double upper = upperOf(child);
            if (upper > lower) queue.push({child, upper});
        }
    }
    return {lower, lower};
}

}  // namespace dropscope
