// ParametricShape::distanceToSurface and normal against the analytic Sphere / Ellipsoid, and against a
// brute-force root scan for the torus (no missed roots).
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "geometry/parametric/ParametricTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace dropscope {
namespace {

using testing::ellipsoidBase;
using testing::randomMatrix;
using testing::Rng;
using testing::sameDistance;
using testing::sphereBase;
using testing::torusBase;
using testing::uniform;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Point uniformInBall(Rng& rng, double radius) {
    for (;;) {
        const Point q = testing::randomPoint(rng, radius);
        if (q.norm() < radius) return q;
    }
}

// Dense random rays from inside, outside and on the surface of a parametric sphere (and of the ellipsoid
// preset) under random affine maps (rotations, anisotropic scalings, shears, reflections, translations) against
// the analytic Ellipsoid: every hit and every miss must agree (no missed roots).
TEST(ParametricDistance, TransformedSphereMatchesEllipsoidOnDenseRays) {
    constexpr int kShapes = 12;
    constexpr int kRaysPerKind = 1000;
    int rays = 0;
    int hits = 0;
    for (int i = 0; i < kShapes; ++i) {
        Rng rng(1000 + static_cast<std::uint64_t>(i));
        const Eigen::Matrix3d m = randomMatrix(rng, i % 2 == 0);
        const Eigen::Vector3d r0 = testing::randomPoint(rng, 3.0);
        const AffineTransform transform(m, r0);
        // Every third shape is the ellipsoid preset with semi-axes D: its image has matrix M^-T D^-2 M^-1.
        const bool onEllipsoid = i % 3 == 2;
        const ParametricShape shape(onEllipsoid ? ellipsoidBase() : sphereBase(), transform);
        const Eigen::Matrix3d baseMatrix = onEllipsoid
                                               ? Eigen::Vector3d(1.0, 4.0, 1.0 / 0.09).asDiagonal().toDenseMatrix()
                                               : Eigen::Matrix3d::Identity();
        const Eigen::Matrix3d inverse = m.inverse();
        const Ellipsoid reference = Ellipsoid::fromMatrix(r0, inverse.transpose() * baseMatrix * inverse);
        const double size = reference.semiAxes().maxCoeff();
        // s is accurate to ~band / |cos|; near-tangent rays lose more, so the tolerance allows 1e-7 of the size.
        const double tol = 1e-7 * size;
        for (int k = 0; k < 3 * kRaysPerKind; ++k) {
            const int kind = k % 3;  // 0 inside, 1 outside, 2 on the surface
            Point p;
            if (kind == 0) {
                const Point q = uniformInBall(rng, 0.999);
                p = transform.apply(onEllipsoid ? Point(q.x(), 0.5 * q.y(), 0.3 * q.z()) : q);
            } else if (kind == 1) {
                p = testing::randomPoint(rng, 2.5 * size, r0);
                if (reference.locatePoint(p) != PointLocation::Outside) continue;
            } else {
                const ParameterDomain dom = shape.surface().domain();
                p = transform.apply(shape.surface().point(uniform(rng, dom.u0, dom.u1), uniform(rng, dom.v0, dom.v1)));
            }
            const Direction d = testing::randomDirection(rng);
            const double expected = reference.distanceToSurface(p, d);
            const double actual = shape.distanceToSurface(p, d);
            ++rays;
            if (!std::isnan(expected)) ++hits;
            ASSERT_TRUE(sameDistance(actual, expected, tol)) << "shape " << i << " ray " << k << " kind " << kind;
        }
    }
    EXPECT_GT(rays, 30000);
    EXPECT_GT(hits, rays / 2);
}

// Rays aimed at the outside of the surface near tangency: the hit/miss decision is still the analytic one except
// within a chord of ~1e-4 of the size (a graze, which may count as a touch).
TEST(ParametricDistance, GrazingRaysAgreeWithSphere) {
    const Sphere reference(Point(0.5, -0.25, 2.0), 1.5);
    const ParametricShape shape(sphereBase(), AffineTransform(1.5 * Eigen::Matrix3d::Identity(), reference.center()));
    Rng rng(5);
    int checked = 0;
    for (int k = 0; k < 1000; ++k) {
        const Direction d = testing::randomDirection(rng);
        // Start 4 radii away, aimed so that the ray passes the centre at an offset near the radius.
        Eigen::Vector3d side = d.vector().cross(testing::randomDirection(rng).vector()).normalized();
        const double offset = 1.5 * (1.0 + uniform(rng, -0.02, 0.02));
        const Point p = reference.center() - 6.0 * d.vector() + offset * side;
        const double expected = reference.distanceToSurface(p, d);
        const double actual = shape.distanceToSurface(p, d);
        // A chord shorter than ~1e-3 of the radius (offset within 5e-7 R of R) is a graze: may count as a touch.
        if (std::abs(offset - 1.5) < 5e-7 * 1.5) continue;
        ++checked;
        ASSERT_TRUE(sameDistance(actual, expected, 1e-7)) << "ray " << k << " offset " << offset;
    }
    EXPECT_GT(checked, 990);
}

TEST(ParametricDistance, NormalMatchesEllipsoid) {
    for (int i = 0; i < 6; ++i) {
        Rng rng(2000 + static_cast<std::uint64_t>(i));
        const Eigen::Matrix3d m = randomMatrix(rng, i % 2 == 1);
        const Eigen::Vector3d r0 = testing::randomPoint(rng, 3.0);
        const AffineTransform transform(m, r0);
        const ParametricShape shape(sphereBase(), transform);
        const Ellipsoid reference = Ellipsoid::fromMatrix(r0, (m * m.transpose()).inverse());
        const ParameterDomain dom = shape.surface().domain();
        for (int k = 0; k < 200; ++k) {
            // Include the poles (u = +-1) of the preset's parametrisation.
            const double u = k < 2 ? (k == 0 ? -1.0 : 1.0) : uniform(rng, dom.u0, dom.u1);
            const Point p = transform.apply(shape.surface().point(u, uniform(rng, dom.v0, dom.v1)));
            const Direction expected = reference.normal(p);
            const Direction actual = shape.normal(p);
            ASSERT_TRUE(expected) << "shape " << i << " point " << k;
            ASSERT_TRUE(actual) << "shape " << i << " point " << k;
            EXPECT_GT(actual.dot(expected), 1.0 - 1e-10) << "shape " << i << " point " << k;
        }
        // Clearly off the surface: no normal.
        EXPECT_FALSE(shape.normal(r0));
        EXPECT_FALSE(shape.normal(r0 + 10.0 * Eigen::Vector3d::Ones()));
    }
}

TEST(ParametricDistance, InvalidInputGivesNaN) {
    const ParametricShape shape(torusBase(), {});
    EXPECT_TRUE(std::isnan(shape.distanceToSurface(Point(5.0, 0.0, 0.0), Direction::invalid())));
    EXPECT_TRUE(std::isnan(shape.distanceToSurface(Point(kNaN, 0.0, 0.0), Direction(1.0, 0.0, 0.0))));
    EXPECT_TRUE(std::isnan(
        shape.distanceToSurface(Point(std::numeric_limits<double>::infinity(), 0.0, 0.0), Direction(-1.0, 0.0, 0.0))));
    EXPECT_FALSE(shape.normal(Point(kNaN, 0.0, 0.0)));
}

// The torus R = 2, r = 0.5 about z: rays through the hole and re-entry after leaving.
TEST(ParametricDistance, TorusRaysThroughTheHole) {
    const ParametricShape torus(torusBase(), {});
    const Direction x(1.0, 0.0, 0.0);
    const double tol = 1e-9;
    EXPECT_NEAR(torus.distanceToSurface(Point(-5.0, 0.0, 0.0), x), 2.5, tol);   // outside: the first of four
    EXPECT_NEAR(torus.distanceToSurface(Point(-2.0, 0.0, 0.0), x), 0.5, tol);   // in the tube
    EXPECT_NEAR(torus.distanceToSurface(Point(0.0, 0.0, 0.0), x), 1.5, tol);    // in the hole
    EXPECT_NEAR(torus.distanceToSurface(Point(-1.5, 0.0, 0.0), x), 3.0, tol);   // leaving into the hole: re-entry
    EXPECT_NEAR(torus.distanceToSurface(Point(-1.5, 0.0, 0.0), -x), 1.0, tol);  // entering: the far side of the tube
    EXPECT_EQ(torus.distanceToSurface(Point(2.5, 0.0, 0.0), x), 0.0);           // leaving for good
    EXPECT_NEAR(torus.distanceToSurface(Point(2.5, 0.0, 0.0), -x), 1.0, tol);   // entering the tube from outside
    EXPECT_TRUE(std::isnan(torus.distanceToSurface(Point(0.0, 0.0, 3.0), Direction(0.0, 0.0, 1.0))));
    EXPECT_TRUE(std::isnan(torus.distanceToSurface(Point(0.0, 0.0, 3.0), Direction(0.0, 0.0, -1.0))));  // the hole
    EXPECT_NEAR(torus.distanceToSurface(Point(2.0, 0.0, 3.0), Direction(0.0, 0.0, -1.0)), 2.5, tol);
    // Along the axis through the hole and then tangent to the top: (0, 0, 0.5) + s x touches at s = 2.
    const std::vector<RayCrossing> all = torus.crossings(Point(-5.0, 0.0, 0.0), x, 0.0);
    ASSERT_EQ(all.size(), 4u);
    EXPECT_NEAR(all[0].s, 2.5, tol);
    EXPECT_NEAR(all[1].s, 3.5, tol);
    EXPECT_NEAR(all[2].s, 6.5, tol);
    EXPECT_NEAR(all[3].s, 7.5, tol);
    EXPECT_LT(all[0].cosine, 0.0);
    EXPECT_GT(all[1].cosine, 0.0);
}

// Implicit form of the torus R = 2, r = 0.5 about z: negative inside.
double torusFunction(const Point& q) {
    const double rho = std::hypot(q.x(), q.y()) - 2.0;
    return rho * rho + q.z() * q.z() - 0.25;
}

Eigen::Vector3d torusGradient(const Point& q) {
    const double h = std::hypot(q.x(), q.y());
    const double rho = h - 2.0;
    return {2.0 * rho * q.x() / h, 2.0 * rho * q.y() / h, 2.0 * q.z()};
}

// The smallest |cos| between the ray and the placed torus's normal at the given crossings.
double leastCosine(const AffineTransform& t, const Point& p, const Direction& d, const std::vector<double>& roots) {
    double least = 1.0;
    for (double s : roots) {
        const Eigen::Vector3d n = t.inverseMatrix().transpose() * torusGradient(t.applyInverse(p + s * d.vector()));
        least = std::min(least, std::abs(d.dot(n.normalized())));
    }
    return least;
}

// Brute force: sign changes of the implicit function along the ray in the base frame, refined by bisection.
std::vector<double> bruteForceRoots(const AffineTransform& t, const Point& p, const Direction& d, double sMax) {
    const Point pb = t.applyInverse(p);
    const Eigen::Vector3d db = t.applyInverseToVector(d.vector());
    constexpr int kSteps = 20000;
    std::vector<double> roots;
    double previous = torusFunction(pb);
    for (int k = 1; k <= kSteps; ++k) {
        const double s1 = sMax * k / kSteps;
        const double f1 = torusFunction(pb + s1 * db);
        if ((previous < 0.0) != (f1 < 0.0)) {
            double lo = sMax * (k - 1) / kSteps, hi = s1;
            for (int b = 0; b < 60; ++b) {
                const double mid = 0.5 * (lo + hi);
                if ((torusFunction(pb + mid * db) < 0.0) == (previous < 0.0))
                    lo = mid;
                else
                    hi = mid;
            }
            roots.push_back(0.5 * (lo + hi));
        }
        previous = f1;
    }
    return roots;
}

// No missed roots on a placed torus: every crossing of a brute-force scan is found, and nothing else.
TEST(ParametricDistance, TorusCrossingsMatchBruteForceScan) {
    int rays = 0;
    int crossings = 0;
    for (int i = 0; i < 3; ++i) {
        Rng rng(3000 + static_cast<std::uint64_t>(i));
        const Eigen::Matrix3d m = randomMatrix(rng, i == 1);
        const AffineTransform transform(m, testing::randomPoint(rng, 2.0));
        const ParametricShape torus(torusBase(), transform);
        const double span = (torus.bounds().max() - torus.bounds().min()).norm();
        for (int k = 0; k < 400; ++k) {
            const Point p = testing::randomPoint(rng, 0.6 * span, torus.bounds().center());
            // Aimed near a random surface point, so that most rays cross the tube (many twice, some four times).
            const double v = uniform(rng, 0.0, 7.0);  // drawn as GCC evaluated the call (RandomGeometry.hpp)
            const double u = uniform(rng, 0.0, 7.0);
            const Point target = transform.apply(torus.surface().point(u, v)) + testing::randomPoint(rng, 0.3);
            const Direction d(target - p);
            const std::vector<double> expected = bruteForceRoots(transform, p, d, 2.0 * span);
            const std::vector<RayCrossing> found = torus.crossings(p, d, 0.0);
            // Skip rays with a near-tangent crossing (a chord shorter than the scan resolves, or a graze).
            if (leastCosine(transform, p, d, expected) < 0.02) continue;
            ++rays;
            crossings += static_cast<int>(expected.size());
            ASSERT_EQ(found.size(), expected.size()) << "torus " << i << " ray " << k;
            for (std::size_t j = 0; j < expected.size(); ++j)
                EXPECT_NEAR(found[j].s, expected[j], 1e-9 * span) << "torus " << i << " ray " << k << " root " << j;
        }
    }
    EXPECT_GT(rays, 1000);
    EXPECT_GT(crossings, 2000);
}

}  // namespace
}  // namespace dropscope
