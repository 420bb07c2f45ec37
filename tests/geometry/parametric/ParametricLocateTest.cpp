// ParametricShape::locatePoint (closest point for the band, crossing parity beyond it) and closestPoint.
#include "geometry/Ellipsoid.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "geometry/parametric/ParametricTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

using testing::Rng;
using testing::sphereBase;
using testing::torusBase;
using testing::uniform;

// This file's cases were drawn without the (0, 2) shear and reflect the third column.
Eigen::Matrix3d randomMatrix(Rng& rng, bool reflect) {
    return testing::randomMatrix(rng, reflect, {.shearXZ = false, .reflectedColumn = 2});
}

const char* name(PointLocation l) {
    switch (l) {
    case PointLocation::Inside: return "inside";
    case PointLocation::OnSurface: return "on surface";
    case PointLocation::Outside: return "outside";
    }
    return "?";
}

TEST(ParametricLocate, TransformedSphereMatchesEllipsoid) {
    int onSurface = 0, inside = 0, outside = 0;
    for (int i = 0; i < 6; ++i) {
        Rng rng(4000 + static_cast<std::uint64_t>(i));
        const Eigen::Matrix3d m = randomMatrix(rng, i % 2 == 0);
        const Eigen::Vector3d r0 = testing::randomPoint(rng, 3.0);
        const AffineTransform transform(m, r0);
        const ParametricShape shape(sphereBase(), transform);
        const Ellipsoid reference = Ellipsoid::fromMatrix(r0, (m * m.transpose()).inverse());
        const ParameterDomain dom = shape.surface().domain();
        for (int k = 0; k < 300; ++k) {
            Point p;
            if (k % 3 == 0) {
                p = transform.apply(shape.surface().point(uniform(rng, dom.u0, dom.u1), uniform(rng, dom.v0, dom.v1)));
            } else {
                const Point q = testing::randomPoint(rng, 1.0);
                p = k % 3 == 1 ? transform.apply(q)
                               : testing::randomPoint(rng, 1.5 * reference.semiAxes().maxCoeff(), r0);
                // Not within 1e-6 of the surface, where the two bands (defined differently) may disagree.
                if (std::abs(std::sqrt(reference.quadraticForm(p)) - 1.0) < 1e-6) continue;
            }
            const PointLocation expected = reference.locatePoint(p);
            const PointLocation actual = shape.locatePoint(p);
            ASSERT_EQ(actual, expected) << "shape " << i << " point " << k << ": " << name(actual) << " vs "
                                        << name(expected);
            onSurface += expected == PointLocation::OnSurface;
            inside += expected == PointLocation::Inside;
            outside += expected == PointLocation::Outside;
        }
    }
    EXPECT_GT(onSurface, 500);
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 300);
}

TEST(ParametricLocate, JustOffTheSurfaceOutsideTheBand) {
    const ParametricShape sphere(sphereBase(), AffineTransform::translation({1.0, 1.0, 1.0}));
    const double band = sphere.surfaceBand();
    Rng rng(9);
    for (int k = 0; k < 100; ++k) {
        const Direction n = testing::randomDirection(rng);
        const Point center(1.0, 1.0, 1.0);
        EXPECT_EQ(sphere.locatePoint(center + (1.0 + 3.0 * band) * n.vector()), PointLocation::Outside) << k;
        EXPECT_EQ(sphere.locatePoint(center + (1.0 - 3.0 * band) * n.vector()), PointLocation::Inside) << k;
        EXPECT_EQ(sphere.locatePoint(center + (1.0 + 0.3 * band) * n.vector()), PointLocation::OnSurface) << k;
    }
}

// Implicit torus R = 2, r = 0.5 about z: < 0 inside.
double torusFunction(const Point& q) {
    const double rho = std::hypot(q.x(), q.y()) - 2.0;
    return rho * rho + q.z() * q.z() - 0.25;
}

// Parity, not the seed's convex two-ray test: points in the hole are outside although rays both ways meet the tube.
TEST(ParametricLocate, TorusParityIncludingTheHole) {
    const ParametricShape base(torusBase(), {});
    EXPECT_EQ(base.locatePoint(Point(0.0, 0.0, 0.0)), PointLocation::Outside);
    EXPECT_EQ(base.locatePoint(Point(0.5, -0.3, 0.1)), PointLocation::Outside);
    EXPECT_EQ(base.locatePoint(Point(2.0, 0.0, 0.0)), PointLocation::Inside);
    EXPECT_EQ(base.locatePoint(Point(0.0, -2.2, 0.3)), PointLocation::Inside);
    EXPECT_EQ(base.locatePoint(Point(1.5, 0.0, 0.0)), PointLocation::OnSurface);
    EXPECT_EQ(base.locatePoint(Point(0.0, 2.0, 0.5)), PointLocation::OnSurface);

    for (int i = 0; i < 3; ++i) {
        Rng rng(5000 + static_cast<std::uint64_t>(i));
        const AffineTransform transform(randomMatrix(rng, i == 2), testing::randomPoint(rng, 2.0));
        const ParametricShape torus(torusBase(), transform);
        int inHole = 0;
        for (int k = 0; k < 300; ++k) {
            // Points in a box around the base torus, half of them in the hole's cylinder.
            Point q = k % 2 == 0 ? Point(uniform(rng, -1.4, 1.4), uniform(rng, -1.4, 1.4), uniform(rng, -0.6, 0.6))
                                 : testing::randomPoint(rng, 2.8);
            if (std::abs(torusFunction(q)) < 1e-6) continue;
            const PointLocation expected = torusFunction(q) < 0.0 ? PointLocation::Inside : PointLocation::Outside;
            inHole += std::hypot(q.x(), q.y()) < 1.5;
            ASSERT_EQ(torus.locatePoint(transform.apply(q)), expected)
                << "torus " << i << " point " << k << " base (" << q.transpose() << ")";
        }
        EXPECT_GT(inHole, 100);
        // Points on the placed surface, the tube's top and bottom circles included.
        for (int k = 0; k < 100; ++k) {
            const double u = uniform(rng, 0.0, 2.0 * std::numbers::pi);
            const double v = k < 10 ? 0.5 * std::numbers::pi : uniform(rng, 0.0, 2.0 * std::numbers::pi);
            const Point p = transform.apply(torus.surface().point(u, v));
            ASSERT_EQ(torus.locatePoint(p), PointLocation::OnSurface) << "torus " << i << " surface point " << k;
        }
    }
}

TEST(ParametricLocate, ClosestPointOnTransformedSphere) {
    // A sphere of radius 2 (a similarity): the distance to its surface is | |p - c| - 2 |.
    const Point c(0.3, -1.0, 2.0);
    Rng rng(11);
    const ParametricShape sphere(sphereBase(), AffineTransform(2.0 * testing::randomRotation(rng), c));
    for (int k = 0; k < 300; ++k) {
        const Point p = testing::randomPoint(rng, 4.0, c);
        const SurfaceProjection nearest = sphere.closestPoint(p);
        EXPECT_NEAR(nearest.distance, std::abs((p - c).norm() - 2.0), 1e-10) << "point " << k;
        // The foot point lies on the ray from the centre through p.
        const Point foot = sphere.transform().apply(sphere.surface().point(nearest.u, nearest.v));
        EXPECT_NEAR((foot - c).normalized().dot((p - c).normalized()), 1.0, 1e-9) << "point " << k;
    }
    // A cutoff: nothing within 0.1 of a point 1 away.
    EXPECT_TRUE(std::isinf(sphere.closestPoint(c + Point(3.0, 0.0, 0.0), 0.1).distance));
}

TEST(ParametricLocate, ClosestPointOnTorusFromTheAxis) {
    // Every point of the inner equator is nearest to the axis point at height 0: distance 1.5.
    const ParametricShape torus(torusBase(), {});
    EXPECT_NEAR(torus.closestPoint(Point(0.0, 0.0, 0.0)).distance, 1.5, 1e-10);
    EXPECT_NEAR(torus.closestPoint(Point(0.0, 0.0, 2.0)).distance, std::hypot(2.0, 2.0) - 0.5, 1e-10);
    EXPECT_NEAR(torus.closestPoint(Point(4.0, 0.0, 0.0)).distance, 1.5, 1e-10);
}

}  // namespace
}  // namespace dropscope
