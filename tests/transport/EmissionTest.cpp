#include "transport/Emission.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope {
namespace {

constexpr int kSamples = 200000;
// Unit vectors built from a few products and one sqrt are unit to a few ulps; 1e-14 is ~45 ulps.
constexpr double kUnitTolerance = 1e-14;

TEST(Emission, PerpendicularBasisIsRightHandedAndOrthonormal) {
    PhotonRandom random(3, 0);
    for (int i = 0; i < 1000; ++i) {
        const Direction d(random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5);
        Eigen::Vector3d u;
        Eigen::Vector3d v;
        perpendicularBasis(d, u, v);
        EXPECT_NEAR(u.norm(), 1.0, kUnitTolerance);
        EXPECT_NEAR(v.norm(), 1.0, kUnitTolerance);
        EXPECT_NEAR(d.dot(u), 0.0, kUnitTolerance);
        EXPECT_NEAR(d.dot(v), 0.0, kUnitTolerance);
        EXPECT_NEAR(u.dot(v), 0.0, kUnitTolerance);
        EXPECT_NEAR(u.cross(v).dot(d.vector()), 1.0, kUnitTolerance);
    }
}

TEST(Emission, RayIsThePencilItselfAndDrawsNothing) {
    const Source source{SourceType::Ray, Point(1, 2, 3), Direction(0, 1, 1), 0.0};
    PhotonRandom random(1, 0);
    const Ray ray = emitPhoton(source, random);
    EXPECT_EQ(ray.origin, source.origin);
    EXPECT_EQ(ray.direction.vector(), source.direction.vector());
    PhotonRandom fresh(1, 0);
    EXPECT_EQ(random.bits(), fresh.bits());
}

TEST(Emission, BeamIsUniformOverItsDisk) {
    // Uniform over a disk of radius R: E[r^2] = R^2/2, Var[r^2] = R^4/12; the azimuth is uniform, so
    // the mean offset is 0; every photon starts in the disk's plane and travels along the axis.
    const Source source{SourceType::Beam, Point(1, -2, 0.5), Direction(1, 2, 2), 2.0};
    double sumR2 = 0.0;
    Eigen::Vector3d sumOffset = Eigen::Vector3d::Zero();
    for (int i = 0; i < kSamples; ++i) {
        PhotonRandom random(5, static_cast<std::uint64_t>(i));
        const Ray ray = emitPhoton(source, random);
        const Eigen::Vector3d offset = ray.origin - source.origin;
        ASSERT_NEAR(offset.dot(source.direction.vector()), 0.0, kUnitTolerance * source.radius);
        ASSERT_LE(offset.norm(), source.radius * (1 + kUnitTolerance));
        ASSERT_EQ(ray.direction.vector(), source.direction.vector());
        sumR2 += offset.squaredNorm();
        sumOffset += offset;
    }
    const double r2 = source.radius * source.radius;
    EXPECT_NEAR(sumR2 / kSamples, r2 / 2, 5.0 * r2 / std::sqrt(12.0 * kSamples));
    EXPECT_LT((sumOffset / kSamples).norm(), 5.0 * source.radius / std::sqrt(2.0 * kSamples));
}

TEST(Emission, PointSourceIsIsotropic) {
    // For an isotropic unit vector each component has mean 0 and E[z^2] = 1/3 (Var[z^2] = 4/45).
    const Source source{SourceType::PointSource, Point(0, 0, 7), Direction(0, 0, 1), 0.0};
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d sumSquares = Eigen::Vector3d::Zero();
    for (int i = 0; i < kSamples; ++i) {
        PhotonRandom random(9, static_cast<std::uint64_t>(i));
        const Ray ray = emitPhoton(source, random);
        ASSERT_EQ(ray.origin, source.origin);
        ASSERT_NEAR(ray.direction.vector().norm(), 1.0, kUnitTolerance);
        sum += ray.direction.vector();
        sumSquares += ray.direction.vector().cwiseProduct(ray.direction.vector());
    }
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(sum[axis] / kSamples, 0.0, 5.0 / std::sqrt(3.0 * kSamples));
        EXPECT_NEAR(sumSquares[axis] / kSamples, 1.0 / 3.0, 5.0 * std::sqrt(4.0 / 45.0 / kSamples));
    }
}

}  // namespace
}  // namespace dropscope
