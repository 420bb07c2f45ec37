#include "optics/Interface.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

using testing::Rng;

const Direction kUp(0.0, 0.0, 1.0);  // outward normal of the plane z = 0 (the medium below)

Direction incoming(double angleFromNormal) {  // travelling down into the plane, in the x-z plane
    return Direction(std::sin(angleFromNormal), 0.0, -std::cos(angleFromNormal));
}

TEST(Refract, NormalIncidenceGoesStraightThrough) {
    const Refraction r = refract(Direction(0, 0, -1), kUp, 1.0, 1.333);
    ASSERT_EQ(r.outcome, InterfaceOutcome::Refracted);
    EXPECT_EQ(r.transmitted.vector(), Eigen::Vector3d(0, 0, -1));
    const Refraction out = refract(Direction(0, 0, 1), kUp, 1.333, 1.0);
    EXPECT_EQ(out.transmitted.vector(), Eigen::Vector3d(0, 0, 1));
}

TEST(Refract, ObliqueEntryObeysScalarSnell) {
    const double n1 = 1.0, n2 = 1.5, incidence = 0.7;
    const Refraction r = refract(incoming(incidence), kUp, n1, n2);
    ASSERT_EQ(r.outcome, InterfaceOutcome::Refracted);
    const double transmittedAngle = std::asin(n1 / n2 * std::sin(incidence));
    EXPECT_NEAR(r.transmitted.x(), std::sin(transmittedAngle), 1e-15);
    EXPECT_NEAR(r.transmitted.y(), 0.0, 1e-15);
    EXPECT_NEAR(r.transmitted.z(), -std::cos(transmittedAngle), 1e-15);
}

TEST(Refract, BeyondTheCriticalAngleIsTotalInternalReflection) {
    const double n1 = 1.333, n2 = 1.0;
    const double critical = std::asin(n2 / n1);
    // leaving the water upward through its top surface (outward normal +z)
    const Direction justBelow(std::sin(critical - 1e-6), 0.0, std::cos(critical - 1e-6));
    const Direction justAbove(std::sin(critical + 1e-6), 0.0, std::cos(critical + 1e-6));
    EXPECT_EQ(refract(justBelow, kUp, n1, n2).outcome, InterfaceOutcome::Refracted);
    EXPECT_EQ(refract(justAbove, kUp, n1, n2).outcome, InterfaceOutcome::TotalInternalReflection);
    // at the critical angle the transmitted ray grazes the surface
    EXPECT_NEAR(refract(justBelow, kUp, n1, n2).transmitted.z(), 0.0, 1e-2);
}

TEST(Refract, TangentRayNeitherEntersNorLeaves) {
    EXPECT_EQ(refract(Direction(1, 0, 0), kUp, 1.0, 1.5).outcome, InterfaceOutcome::Tangent);
}

// Seed eq. 4.7 against the scalar law over random geometry: unit length, coplanar with i and n, on
// the far side of the surface, and n1 sin(i) = n2 sin(t).
TEST(Refract, VectorFormMatchesScalarSnellEverywhere) {
    int refracted = 0;
    for (int k = 0; k < 20000; ++k) {
        SCOPED_TRACE(k);
        Rng rng(static_cast<unsigned>(k));
        const Direction i = testing::randomDirection(rng);
        const Direction n = testing::randomDirection(rng);
        const double n1 = testing::uniform(rng, 1.0, 2.0);
        const double n2 = testing::uniform(rng, 1.0, 2.0);
        const Refraction r = refract(i, n, n1, n2);
        const double sinI = i.vector().cross(n.vector()).norm();
        if (n1 / n2 * sinI > 1.0) {
            EXPECT_EQ(r.outcome, InterfaceOutcome::TotalInternalReflection);
            continue;
        }
        ASSERT_EQ(r.outcome, InterfaceOutcome::Refracted);
        ++refracted;
        const Eigen::Vector3d& t = r.transmitted.vector();
        EXPECT_NEAR(t.norm(), 1.0, 1e-14);
        EXPECT_NEAR(t.dot(i.vector().cross(n.vector())), 0.0, 1e-14);                 // coplanar
        EXPECT_EQ(std::signbit(t.dot(n.vector())), std::signbit(i.dot(n.vector())));  // crosses over
        EXPECT_NEAR(n1 * sinI, n2 * t.cross(n.vector()).norm(), 1e-13);
    }
    EXPECT_GT(refracted, 10000);
}

TEST(Reflect, MirrorsTheNormalComponent) {
    const Direction r = reflect(incoming(0.3), kUp);
    EXPECT_NEAR(r.x(), std::sin(0.3), 1e-15);
    EXPECT_NEAR(r.z(), std::cos(0.3), 1e-15);
    const Direction back = reflect(incoming(0.3), -kUp);  // either orientation of the normal
    EXPECT_TRUE(back.vector().isApprox(r.vector(), 1e-15));
}

}  // namespace
}  // namespace dropscope
