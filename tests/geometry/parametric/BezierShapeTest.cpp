// ParametricShape on a Bezier surface: the flattened droplet asset (2 x 4 bicubic patches, a pole at each end of
// u). Mesh normals and normal(p) at and near the poles, ray crossings against a brute-force fine triangulation of
// the surface refined by Newton, locatePoint against the parity of that reference, volume under a transform.
#include "geometry/parametric/BezierAsset.hpp"
#include "geometry/parametric/BezierSurface.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "geometry/parametric/ParametricTestSupport.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace dropscope {
namespace {

using testing::randomMatrix;
using testing::Rng;
using testing::sameDistance;
using testing::uniform;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The asset's poles (rows run from north to south) and its parameter domain [0, 2] x [0, 4].
const Point kNorthPole(0.0, 0.0, 1.0);
const Point kSouthPole(0.0, 0.0, -0.6);
constexpr double kURange = 2.0;
constexpr double kVRange = 4.0;
// The outward normal at the north pole, and at the south pole.
const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();
const Eigen::Vector3d kDown = -Eigen::Vector3d::UnitZ();

// A crossing the reference may get wrong, or miss, lies within this |cos| of tangency. The fine triangulation
// (256 x 512 quads) strays from the surface by delta ~ h^2 kappa / 8 ~ 6e-5 (h ~ 0.0125, kappa <~ 3 at the rim);
// a ray crossing one and not the other passes within delta of a tangent point, at an angle ~ sqrt(2 delta kappa)
// ~ 0.02 rad. 0.05 adds margin. Only rays whose results differ are checked against it.
constexpr double kTangencyCosine = 0.05;

const std::shared_ptr<const ParametricBase>& dropletBase() {
    static const auto base = makeParametricBase(makeBezierSurface(testing::flattenedDropletPatches()));
    return base;
}

// The transforms the tests run under: the identity, and random non-similar ones (one of them a reflection).
std::vector<AffineTransform> testTransforms() {
    std::vector<AffineTransform> transforms{AffineTransform()};
    for (int i = 0; i < 2; ++i) {
        Rng rng(700 + static_cast<std::uint64_t>(i));
        transforms.emplace_back(randomMatrix(rng, i == 1), testing::randomPoint(rng, 2.0));
    }
    return transforms;
}

// The base surface's outward normal at (u, v) from its own derivatives, the poles' known normals there (the asset
// is built so that r_u x r_v points outward: its signed volume is positive).
Eigen::Vector3d referenceBaseNormal(const ParametricSurface& surface, double u, double v) {
    if (u <= 0.0) return kUp;
    if (u >= kURange) return kDown;
    const SurfaceJet jet = surface.jet(u, v);
    return jet.ru.cross(jet.rv).normalized();
}

// Brute force: the ray against a fine triangulation of the whole parameter domain (kU x kV quads, two triangles
// each, bounded in blocks of kBlock x kBlock quads), every hit refined by Newton on p + s d = r(u, v) (seed 000
// eqs. 1.76, 1.77) from where it met its triangle; where Newton does not converge near that triangle, by
// triangulating the 3 x 3 cells around the hit ever more finely. The triangulation is closed (a pole row is one
// point), so a transverse crossing of the surface is a crossing of it: nothing is missed but grazes.
class FineTriangulation {
public:
    static constexpr int kU = 256;
    static constexpr int kV = 512;
    static constexpr int kBlock = 8;

    struct Root {
        double s;
        double u;
        double v;
    };

    explicit FineTriangulation(const ParametricSurface& surface) : surface_(surface) {
        vertices_.resize(static_cast<std::size_t>((kU + 1) * kV));
        for (int i = 0; i <= kU; ++i)
            for (int j = 0; j < kV; ++j) vertex(i, j) = surface.point(uAt(i), vAt(j));
        for (int bi = 0; bi < kU / kBlock; ++bi)
            for (int bj = 0; bj < kV / kBlock; ++bj) {
                Eigen::AlignedBox3d box;
                for (int i = bi * kBlock; i <= (bi + 1) * kBlock; ++i)
                    for (int j = bj * kBlock; j <= (bj + 1) * kBlock; ++j) box.extend(vertex(i, j % kV));
                blocks_.push_back(box);
            }
    }

    // Every crossing with s > sMin of the ray p + s d given in the base frame (d need not be unit), nearest first.
    std::vector<Root> roots(const Point& p, const Eigen::Vector3d& d, double sMin) const {
        std::vector<Root> found;
        const int blocksV = kV / kBlock;
        for (std::size_t b = 0; b < blocks_.size(); ++b) {
            if (!meets(blocks_[b], p, d)) continue;
            const int bi = static_cast<int>(b) / blocksV, bj = static_cast<int>(b) % blocksV;
            for (int i = bi * kBlock; i < (bi + 1) * kBlock; ++i)
                for (int j = bj * kBlock; j < (bj + 1) * kBlock; ++j) {
                    const double du = kURange / kU, dv = kVRange / kV;
                    hitQuad(vertex(i, j), vertex(i + 1, j), vertex(i + 1, (j + 1) % kV), vertex(i, (j + 1) % kV),
                            uAt(i), vAt(j), du, dv, p, d,
                            [&](double s, double u, double v) { found.push_back(refine(p, d, s, u, v, du, dv)); });
                }
        }
        std::sort(found.begin(), found.end(), [](const Root& a, const Root& b) { return a.s < b.s; });
        std::vector<Root> result;
        for (const Root& r : found) {
            if (!(r.s > sMin)) continue;
            // The same root met in two triangles (across their shared edge).
            if (!result.empty() && r.s - result.back().s <= 1e-9 * (1.0 + std::abs(r.s))) continue;
            result.push_back(r);
        }
        return result;
    }

    // The world-frame cosine between the world ray direction d and the outward normal at (u, v).
    double cosine(const AffineTransform& t, const Eigen::Vector3d& d, const Root& r) const {
        const Eigen::Vector3d n = t.inverseMatrix().transpose() * referenceBaseNormal(surface_, r.u, r.v);
        return d.dot(n.normalized());
    }

    // The enclosed volume of a kU x kV (or coarser, by `stride`) triangulation: sum of a . (b x c) / 6.
    double meshVolume(int stride) const {
        double volume = 0.0;
        for (int i = 0; i < kU; i += stride)
            for (int j = 0; j < kV; j += stride) {
                const Point& a = vertex(i, j);
                const Point& b = vertex(i + stride, j);
                const Point& c = vertex(i + stride, (j + stride) % kV);
                const Point& e = vertex(i, (j + stride) % kV);
                volume += (a.dot(b.cross(c)) + a.dot(c.cross(e))) / 6.0;
            }
        return volume;
    }

private:
    static double uAt(int i) { return i == kU ? kURange : kURange * i / kU; }
    static double vAt(int j) { return kVRange * j / kV; }
    Point& vertex(int i, int j) { return vertices_[static_cast<std::size_t>(i * kV + j)]; }
    const Point& vertex(int i, int j) const { return vertices_[static_cast<std::size_t>(i * kV + j)]; }

    static bool meets(const Eigen::AlignedBox3d& box, const Point& p, const Eigen::Vector3d& d) {
        double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double pad = 1e-12 * (1.0 + std::abs(box.min()[k]) + std::abs(box.max()[k]));
            if (d[k] == 0.0) {
                if (p[k] < box.min()[k] - pad || p[k] > box.max()[k] + pad) return false;
                continue;
            }
            const double ta = (box.min()[k] - pad - p[k]) / d[k], tb = (box.max()[k] + pad - p[k]) / d[k];
            lo = std::max(lo, std::min(ta, tb));
            hi = std::min(hi, std::max(ta, tb));
        }
        return lo <= hi;
    }

    // The quad (a, b, c, e) at parameters (u, v) .. (u + du, v + dv) as triangles (a, b, c) and (a, c, e), the
    // mesh's split; calls hit(s, u, v) for each triangle the ray meets (edges included, with a rounding margin).
    template <class Hit>
    static void hitQuad(const Point& a, const Point& b, const Point& c, const Point& e, double u, double v, double du,
                        double dv, const Point& p, const Eigen::Vector3d& d, const Hit& hit) {
        const auto triangle = [&](const Point& q0, const Point& q1, const Point& q2, const Eigen::Vector2d& w0,
                                  const Eigen::Vector2d& w1, const Eigen::Vector2d& w2) {
            const Eigen::Vector3d e1 = q1 - q0, e2 = q2 - q0;
            const Eigen::Vector3d h = d.cross(e2);
            const double det = e1.dot(h);
            if (!(std::abs(det) > 0.0)) return;
            const Eigen::Vector3d t = p - q0;
            const double beta = t.dot(h) / det;
            const Eigen::Vector3d q = t.cross(e1);
            const double gamma = d.dot(q) / det;
            constexpr double kEdge = 1e-9;
            if (beta < -kEdge || gamma < -kEdge || beta + gamma > 1.0 + kEdge) return;
            const Eigen::Vector2d w = w0 + beta * (w1 - w0) + gamma * (w2 - w0);
            hit(e2.dot(q) / det, w.x(), w.y());
        };
        const Eigen::Vector2d wa(u, v), wb(u + du, v), wc(u + du, v + dv), we(u, v + dv);
        triangle(a, b, c, wa, wb, wc);
        triangle(a, c, e, wa, wc, we);
    }

    Root refine(const Point& p, const Eigen::Vector3d& d, double s, double u, double v, double du, double dv) const {
        const double u0 = u, v0 = v;
        for (int iteration = 0; iteration < 40; ++iteration) {
            const SurfaceJet jet =
                surface_.jet(std::clamp(u, 0.0, kURange), std::fmod(std::fmod(v, kVRange) + kVRange, kVRange));
            const Eigen::Vector3d f = p + s * d - jet.r;
            if (f.norm() <= 1e-14 * (1.0 + p.norm() + std::abs(s) * d.norm())) {
                // Converged near where the triangulation met the ray: the same root.
                if (std::abs(u - u0) <= 2.0 * du && std::abs(v - v0) <= 2.0 * dv)
                    return {s, std::clamp(u, 0.0, kURange), v};
                break;
            }
            Eigen::Matrix3d jacobian;
            jacobian << -jet.ru, -jet.rv, d;
            const Eigen::FullPivLU<Eigen::Matrix3d> lu(jacobian);
            if (!lu.isInvertible()) break;
            const Eigen::Vector3d step = -lu.solve(f);
            u += step[0];
            v += step[1];
            s += step[2];
            if (u < 0.0 || u > kURange || !std::isfinite(s)) break;
        }
        return subdivide(p, d, s, u0, v0, du, dv);
    }

    // Newton failed (next to a pole, where (u, v) are polar-like coordinates): triangulate the 3 x 3 cells of size
    // (du, dv) around (u, v) 8 x 8 times finer, keep the hit nearest s, and again, until the cells are ~1e-13 small.
    Root subdivide(const Point& p, const Eigen::Vector3d& d, double s, double u, double v, double du, double dv) const {
        constexpr int kFine = 8;
        for (int level = 0; level < 12 && du > 1e-13; ++level) {
            const double fu = du / kFine, fv = dv / kFine;
            const double uStart = std::max(0.0, u - du - std::fmod(u, fu)), uEnd = std::min(kURange, u + 2.0 * du);
            const double vStart = v - dv - std::fmod(v, fv);
            bool found = false;
            Root best{s, u, v};
            for (double uc = uStart; uc < uEnd - 0.5 * fu; uc += fu)
                for (int k = 0; k < 3 * kFine; ++k) {
                    const double vc = vStart + k * fv;
                    const double u1 = std::min(uc + fu, kURange);
                    hitQuad(surface_.point(uc, vc), surface_.point(u1, vc), surface_.point(u1, vc + fv),
                            surface_.point(uc, vc + fv), uc, vc, u1 - uc, fv, p, d,
                            [&](double hs, double hu, double hv) {
                                if (!found || std::abs(hs - s) < std::abs(best.s - s)) best = {hs, hu, hv};
                                found = true;
                            });
                }
            if (!found) break;
            s = best.s;
            u = best.u;
            v = best.v;
            du = fu;
            dv = fv;
        }
        ++subdivided;
        return {s, u, std::fmod(std::fmod(v, kVRange) + kVRange, kVRange)};
    }

    const ParametricSurface& surface_;
    std::vector<Point> vertices_;
    std::vector<Eigen::AlignedBox3d> blocks_;

public:
    mutable int subdivided = 0;  // roots Newton did not refine
};

const FineTriangulation& reference() {
    static const FineTriangulation fine(dropletBase()->surface());
    return fine;
}

// Per-vertex: the placed mesh's normal against the mean of its adjacent faces' unit normals.
TEST(BezierShape, MeshNormalsAgreeWithFacesAtEveryVertex) {
    for (const AffineTransform& transform : testTransforms()) {
        const ParametricShape shape(dropletBase(), transform);
        const SurfaceMesh mesh = shape.mesh();
        ASSERT_EQ(mesh.vertices.size(), mesh.normals.size());
        std::vector<Eigen::Vector3d> faceSum(mesh.vertices.size(), Eigen::Vector3d::Zero());
        for (const auto& t : mesh.triangles) {
            const Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                          .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                                          .normalized();
            for (std::uint32_t k : t) faceSum[k] += n;
        }
        const Point north = transform.apply(kNorthPole), south = transform.apply(kSouthPole);
        const double size = (shape.bounds().max() - shape.bounds().min()).norm();
        int poleVertices = 0;
        double leastCosine = 1.0;
        for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
            ASSERT_GT(faceSum[k].norm(), 0.0) << "vertex " << k << " has no face";
            ASSERT_NEAR(mesh.normals[k].norm(), 1.0, 1e-12) << "vertex " << k;
            const double cosine = mesh.normals[k].dot(faceSum[k].normalized());
            leastCosine = std::min(leastCosine, cosine);
            EXPECT_GT(cosine, 0.9) << "vertex " << k << " at " << mesh.vertices[k].transpose();
            const bool atPole =
                (mesh.vertices[k] - north).norm() < 1e-12 * size || (mesh.vertices[k] - south).norm() < 1e-12 * size;
            if (atPole) {
                ++poleVertices;
                const Eigen::Vector3d exact =
                    transform.applyToNormal((mesh.vertices[k] - north).norm() < 1e-12 * size ? kUp : kDown).vector();
                EXPECT_GT(mesh.normals[k].dot(exact), 1.0 - 1e-12) << "pole vertex " << k;
            }
        }
        EXPECT_GT(poleVertices, 20);
        std::cout << "mesh: " << mesh.vertices.size() << " vertices (" << poleVertices
                  << " at the poles), least cos(vertex normal, mean face normal) " << leastCosine << "\n";
    }
}

// normal(p) at the poles (p on them, and a fraction of a band off them) and next to them, where r_u x r_v vanishes.
TEST(BezierShape, NormalAtAndNearThePoles) {
    const ParametricSurface& surface = dropletBase()->surface();
    for (const AffineTransform& transform : testTransforms()) {
        const ParametricShape shape(dropletBase(), transform);
        const double band = shape.surfaceBand();
        for (int pole = 0; pole < 2; ++pole) {
            const Eigen::Vector3d baseNormal = pole == 0 ? kUp : kDown;
            const Point at = transform.apply(pole == 0 ? kNorthPole : kSouthPole);
            const Eigen::Vector3d exact = transform.applyToNormal(baseNormal).vector();
            for (double off : {0.0, 0.5, -0.5}) {
                const Direction n = shape.normal(at + off * band * exact);
                ASSERT_TRUE(n) << "pole " << pole << " off " << off;
                EXPECT_GT(n.dot(exact), 1.0 - 1e-12) << "pole " << pole << " off " << off;
            }
            // Points a parameter distance eps from the pole: the normal tilts by ~kappa * distance from the pole's.
            for (double eps : {1e-15, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2}) {
                for (int k = 0; k < 8; ++k) {
                    const double u = pole == 0 ? eps : kURange - eps;
                    const double v = kVRange * (k + 0.37) / 8.0;
                    const Point q = transform.apply(surface.point(u, v));
                    const Direction n = shape.normal(q);
                    ASSERT_TRUE(n) << "pole " << pole << " eps " << eps << " k " << k;
                    const double distance = (q - at).norm();
                    // The normal there from the derivatives, where they are far from vanishing; the pole's closer in.
                    const Eigen::Vector3d expected =
                        eps >= 1e-4 ? transform.applyToNormal(referenceBaseNormal(surface, u, v)).vector() : exact;
                    const double allowed = eps >= 1e-4 ? 1e-9 : 1e-9 + 10.0 * distance;
                    EXPECT_LT(std::atan2(n.vector().cross(expected).norm(), n.dot(expected)), allowed)
                        << "pole " << pole << " eps " << eps << " k " << k;
                }
            }
        }
    }
}

// Closest points and rays at and next to a pole: the pole is found, and a ray through it crosses once there.
TEST(BezierShape, ClosestPointsAndRaysAtThePoles) {
    const ParametricSurface& surface = dropletBase()->surface();
    Rng rng(41);
    for (const AffineTransform& transform : testTransforms()) {
        const ParametricShape shape(dropletBase(), transform);
        const double size = (shape.bounds().max() - shape.bounds().min()).norm();
        for (int pole = 0; pole < 2; ++pole) {
            const Point at = transform.apply(pole == 0 ? kNorthPole : kSouthPole);
            const Direction outward = transform.applyToNormal(pole == 0 ? kUp : kDown);
            // Along the normal, inside and out, the pole is the nearest point (convex, curvature radius > 0.05).
            for (double h : {1e-9, 1e-6, 1e-3, 0.03}) {
                for (double sign : {1.0, -1.0}) {
                    const SurfaceProjection nearest = shape.closestPoint(at + sign * h * outward.vector());
                    EXPECT_NEAR(nearest.distance, h, 1e-12 * size) << "pole " << pole << " h " << h << " sign " << sign;
                }
            }
            // Rays aimed at the pole and at points eps from it, from outside and from inside.
            // Every query next to a pole searches all the leaves that touch it (~0.1 ms): 60 rays per pole.
            for (int k = 0; k < 60; ++k) {
                const double eps = k % 4 == 0 ? 0.0 : std::pow(10.0, -uniform(rng, 1.0, 14.0));
                const double u = pole == 0 ? eps : kURange - eps;
                const Point target = transform.apply(surface.point(u, uniform(rng, 0.0, kVRange)));
                Eigen::Vector3d w = testing::randomDirection(rng).vector();
                if (w.dot(outward.vector()) < 0.0) w = -w;
                if (w.dot(outward.vector()) < 0.2) w = (w + outward.vector()).normalized();
                const double t = uniform(rng, 0.01, 1.0) * size;
                const Direction in(-w);
                // From outside: the first crossing is the target, entering.
                EXPECT_NEAR(shape.distanceToSurface(target + t * w, in), t, 1e-9 * size)
                    << "pole " << pole << " ray " << k;
                const std::vector<RayCrossing> all = shape.crossings(target + t * w, in, 0.0);
                ASSERT_EQ(all.size(), 2u) << "pole " << pole << " ray " << k;
                EXPECT_LT(all[0].cosine, -0.1) << "pole " << pole << " ray " << k;
                EXPECT_GT(all[1].cosine, 0.1) << "pole " << pole << " ray " << k;
                // From just inside, leaving through the target.
                const double tin = 1e-3 * size;
                EXPECT_NEAR(shape.distanceToSurface(target - tin * w, Direction(w)), tin, 1e-9 * size)
                    << "pole " << pole << " ray " << k;
                EXPECT_EQ(shape.locatePoint(target - tin * w), PointLocation::Inside)
                    << "pole " << pole << " ray " << k;
                EXPECT_EQ(shape.locatePoint(target + tin * w), PointLocation::Outside)
                    << "pole " << pole << " ray " << k;
                EXPECT_EQ(shape.locatePoint(target), PointLocation::OnSurface) << "pole " << pole << " ray " << k;
            }
        }
    }
}

// Dense random rays from outside (half of them aimed at the surface, a tenth at a pole), inside and from surface
// points, untransformed and under random non-similar maps, against the fine triangulation: every hit and miss and
// every distance agree, except where a crossing (the engine's or the reference's) is within kTangencyCosine of
// tangency.
TEST(BezierShape, DistanceMatchesFineTriangulation) {
    const ParametricSurface& surface = dropletBase()->surface();
    const FineTriangulation& fine = reference();
    constexpr int kRaysPerTransform = 1200;
    int rays = 0, hits = 0, tangentExemptions = 0;
    for (const AffineTransform& transform : testTransforms()) {
        Rng rng(5000 + static_cast<std::uint64_t>(rays));
        const ParametricShape shape(dropletBase(), transform);
        const double size = (shape.bounds().max() - shape.bounds().min()).norm();
        const double tol = 1e-7 * size;
        for (int k = 0; k < kRaysPerTransform; ++k) {
            const int kind = k % 3;  // 0 outside, 1 inside, 2 on the surface
            const double u = k % 10 == 0 ? std::pow(10.0, -uniform(rng, 0.5, 6.0)) * (k % 20 == 0 ? 1.0 : -1.0) +
                                               (k % 20 == 0 ? 0.0 : kURange)
                                         : uniform(rng, 0.0, kURange);
            const Point onSurface = transform.apply(surface.point(u, uniform(rng, 0.0, kVRange)));
            Point p;
            Direction d = testing::randomDirection(rng);
            if (kind == 0) {
                p = testing::randomPoint(rng, 1.5 * size, shape.bounds().center());
                if (k % 2 == 0) d = Direction(onSurface + testing::randomPoint(rng, 0.02 * size) - p);
            } else if (kind == 1) {
                // The droplet is convex around its origin: scaled-down surface points are inside.
                p = transform.apply(uniform(rng, 0.0, 0.98) * transform.applyInverse(onSurface));
            } else {
                p = onSurface;
            }
            if (kind == 0 && shape.locatePoint(p) != PointLocation::Outside) continue;
            const Point pBase = transform.applyInverse(p);
            const Eigen::Vector3d dBase = transform.applyInverseToVector(d.vector());
            const std::vector<FineTriangulation::Root> roots = fine.roots(pBase, dBase, -1.0);
            double expected = kNaN;
            for (const auto& r : roots) {
                if (r.s > (kind == 2 ? 1e-7 * size : 0.0)) {
                    expected = r.s;
                    break;
                }
            }
            if (kind == 2 && std::isnan(expected)) expected = 0.0;
            const double actual = shape.distanceToSurface(p, d);
            ++rays;
            if (!std::isnan(expected)) ++hits;
            if (sameDistance(actual, expected, tol)) continue;
            // A disagreement is allowed only next to tangency.
            double least = 1.0;
            for (const auto& r : roots)
                if (r.s > -1e-7 * size) least = std::min(least, std::abs(fine.cosine(transform, d.vector(), r)));
            for (const RayCrossing& c : shape.crossings(p, d, -1e-7 * size))
                least = std::min(least, std::abs(c.cosine));
            ASSERT_LT(least, kTangencyCosine) << "transform " << rays / kRaysPerTransform << " ray " << k << " kind "
                                              << kind << ": parametric " << actual << " vs reference " << expected;
            ++tangentExemptions;
        }
    }
    std::cout << rays << " rays, " << hits << " hits, " << tangentExemptions << " near-tangent disagreements, "
              << fine.subdivided << " reference roots refined by subdivision\n";
    EXPECT_GT(rays, 3000);
    EXPECT_GT(hits, rays / 2);
    EXPECT_LT(tangentExemptions, rays / 200);
}

// locatePoint against the parity of the reference's crossings along a random ray.
TEST(BezierShape, LocatePointMatchesReferenceParity) {
    const FineTriangulation& fine = reference();
    int points = 0, inside = 0;
    for (const AffineTransform& transform : testTransforms()) {
        Rng rng(6000 + static_cast<std::uint64_t>(points));
        const ParametricShape shape(dropletBase(), transform);
        const double size = (shape.bounds().max() - shape.bounds().min()).norm();
        for (int k = 0; k < 300; ++k) {
            const Point p = testing::randomPoint(rng, 0.4 * size, shape.bounds().center());
            bool decided = false, parityInside = false;
            for (int attempt = 0; attempt < 4 && !decided; ++attempt) {
                const Direction d = testing::randomDirection(rng);
                const auto roots =
                    fine.roots(transform.applyInverse(p), transform.applyInverseToVector(d.vector()), 0.0);
                decided = true;
                for (const auto& r : roots)
                    if (r.s < 1e-6 * size || std::abs(fine.cosine(transform, d.vector(), r)) < kTangencyCosine)
                        decided = false;
                parityInside = roots.size() % 2 == 1;
            }
            if (!decided) continue;
            ++points;
            if (parityInside) ++inside;
            EXPECT_EQ(shape.locatePoint(p), parityInside ? PointLocation::Inside : PointLocation::Outside)
                << "transform " << points / 300 << " point " << k;
        }
    }
    EXPECT_GT(points, 850);
    EXPECT_GT(inside, points / 10);
}

// |det M| times the base volume, which the fine triangulation's volume confirms (Richardson on h^2).
TEST(BezierShape, VolumeUnderTransform) {
    const FineTriangulation& fine = reference();
    const double coarse = fine.meshVolume(2), finest = fine.meshVolume(1);
    const double extrapolated = (4.0 * finest - coarse) / 3.0;
    const double baseVolume = std::abs(dropletBase()->signedVolume());
    EXPECT_GT(dropletBase()->signedVolume(), 0.0);
    EXPECT_NEAR(baseVolume / extrapolated, 1.0, 1e-7);
    for (const AffineTransform& transform : testTransforms()) {
        const ParametricShape shape(dropletBase(), transform);
        EXPECT_NEAR(shape.volume(), std::abs(transform.matrix().determinant()) * extrapolated, 1e-7 * shape.volume());
    }
}

}  // namespace
}  // namespace dropscope
