#include "geometry/AffineTransform.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {
namespace {

using testing::Rng;

constexpr double kExact = 1e-14;

Eigen::Matrix<double, 6, 1> shearFactors(double xy, double xz, double yx, double yz, double zx, double zy) {
    Eigen::Matrix<double, 6, 1> f;
    f << xy, xz, yx, yz, zx, zy;
    return f;
}

TEST(AffineTransform, RotationTurnsXIntoYAboutZ) {  // seed A.1-A.2
    const AffineTransform r = AffineTransform::rotation(Eigen::Vector3d(0, 0, 2), std::numbers::pi / 2);
    EXPECT_TRUE(r.apply(Point(1, 0, 0)).isApprox(Point(0, 1, 0), kExact));
    EXPECT_NEAR(r.determinant(), 1.0, kExact);
    EXPECT_TRUE((r.matrix() * r.matrix().transpose()).isApprox(Eigen::Matrix3d::Identity(), kExact));
    EXPECT_TRUE(r.classification().isSimilarity);
    EXPECT_NEAR(r.classification().uniformScale, 1.0, kExact);
    EXPECT_FALSE(r.classification().reflects);
}

TEST(AffineTransform, ReflectionFlipsTheNormalAndKeepsThePlane) {  // seed A.3
    const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2) / 3.0;
    const AffineTransform f = AffineTransform::reflection(3.0 * n);
    EXPECT_TRUE(f.apply(n).isApprox(-n, kExact));
    const Eigen::Vector3d inPlane = n.cross(Eigen::Vector3d(0, 0, 1));
    EXPECT_TRUE(f.apply(inPlane).isApprox(inPlane, kExact));
    EXPECT_NEAR(f.determinant(), -1.0, kExact);
    EXPECT_TRUE(f.classification().reflects);
    EXPECT_TRUE(f.classification().isSimilarity);
}

TEST(AffineTransform, ScalingAndShearHaveTheSeedsLayout) {  // seed A.4-A.6
    const AffineTransform k = AffineTransform::scaling(Eigen::Vector3d(2, 3, 4));
    EXPECT_EQ(k.matrix(), Eigen::Vector3d(2, 3, 4).asDiagonal().toDenseMatrix());
    EXPECT_FALSE(k.classification().isSimilarity);
    EXPECT_NEAR(k.classification().singularValues[0], 4.0, kExact);
    const AffineTransform u = AffineTransform::uniformScaling(-2.5);
    EXPECT_TRUE(u.classification().isSimilarity);
    EXPECT_NEAR(u.classification().uniformScale, 2.5, kExact);
    EXPECT_TRUE(u.classification().reflects);

    const AffineTransform s = AffineTransform::shear(shearFactors(0.1, 0.2, 0.3, 0.4, 0.5, 0.6));
    Eigen::Matrix3d expected;
    expected << 1, 0.1, 0.2, 0.3, 1, 0.4, 0.5, 0.6, 1;
    EXPECT_EQ(s.matrix(), expected);
    EXPECT_FALSE(s.classification().isSimilarity);
}

TEST(AffineTransform, ThenAppliesTheSecondAfterTheFirst) {
    const AffineTransform scale = AffineTransform::scaling(Eigen::Vector3d(2, 1, 1));
    const AffineTransform move = AffineTransform::translation(Eigen::Vector3d(0, 0, 5));
    const AffineTransform turn = AffineTransform::rotation(Eigen::Vector3d(0, 0, 1), std::numbers::pi / 2);
    const AffineTransform all = scale.then(turn).then(move);
    // (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (0, 2, 5)
    EXPECT_TRUE(all.apply(Point(1, 0, 0)).isApprox(Point(0, 2, 5), kExact));
    Rng rng(7);
    for (int i = 0; i < 20; ++i) {
        const Point p = testing::randomPoint(rng, 3.0);
        EXPECT_TRUE(all.applyInverse(all.apply(p)).isApprox(p, 1e-13)) << "case " << i;
        EXPECT_TRUE(all.apply(p).isApprox(move.apply(turn.apply(scale.apply(p))), kExact)) << "case " << i;
    }
}

TEST(AffineTransform, SingularOrNonFiniteInputIsRefused) {
    EXPECT_THROW(AffineTransform::scaling(Eigen::Vector3d(1, 0, 1)), std::invalid_argument);
    EXPECT_THROW(AffineTransform::shear(shearFactors(1, 0, 1, 0, 0, 0)), std::invalid_argument);  // rows x and y equal
    EXPECT_THROW(AffineTransform::rotation(Eigen::Vector3d::Zero(), 1.0), std::invalid_argument);
    EXPECT_THROW(AffineTransform::reflection(Eigen::Vector3d(NAN, 0, 0)), std::invalid_argument);
    Eigen::Matrix3d rankTwo;
    rankTwo << 1, 2, 3, 4, 5, 6, 7, 8, 9;
    EXPECT_THROW(AffineTransform(rankTwo, Eigen::Vector3d::Zero()), std::invalid_argument);
    EXPECT_THROW(AffineTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, INFINITY, 0)), std::invalid_argument);
    try {
        AffineTransform(rankTwo, Eigen::Vector3d::Zero());
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("singular"), std::string::npos) << error.what();
    }
}

TEST(AffineTransform, NormalsStayPerpendicularToMappedTangents) {
    Rng rng(11);
    for (int i = 0; i < 50; ++i) {
        Eigen::Matrix3d m = Eigen::Matrix3d::Random() + 2.0 * Eigen::Matrix3d::Identity();
        const AffineTransform t(m, testing::randomPoint(rng, 1.0));
        const Eigen::Vector3d n = testing::randomDirection(rng).vector();
        const Eigen::Vector3d tangent = n.cross(testing::randomDirection(rng).vector());
        const Direction mapped = t.applyToNormal(n);
        EXPECT_NEAR(mapped.dot(t.applyToVector(tangent)), 0.0, 1e-12 * tangent.norm() * m.norm()) << "case " << i;
    }
}

// Under a reflection the image of an outward normal must still point out: the plane z = 0 bounding the
// half-space z < 0 (outward normal +z), mirrored in x = y and then turned, bounds the image of that
// half-space, and the mapped normal points away from the image of an inside point.
TEST(AffineTransform, NormalsStayOutwardUnderReflections) {
    Rng rng(12);
    for (int i = 0; i < 50; ++i) {
        const AffineTransform t =
            AffineTransform::reflection(testing::randomDirection(rng).vector())
                .then(AffineTransform(testing::randomRotation(rng) * Eigen::Vector3d(1, 2, 0.5).asDiagonal(),
                                      testing::randomPoint(rng, 1.0)));
        ASSERT_TRUE(t.classification().reflects);
        const Point onSurface = testing::randomPoint(rng, 1.0).cwiseProduct(Eigen::Vector3d(1, 1, 0));
        const Point inside = onSurface - Eigen::Vector3d::UnitZ();
        const Direction n = t.applyToNormal(Eigen::Vector3d::UnitZ());
        EXPECT_LT(n.dot(t.apply(inside) - t.apply(onSurface)), 0.0) << "case " << i;
        // And it is the normal of the image plane: perpendicular to the images of x and y.
        EXPECT_NEAR(n.dot(t.applyToVector(Eigen::Vector3d::UnitX())), 0.0, 1e-13) << "case " << i;
        EXPECT_NEAR(n.dot(t.applyToVector(Eigen::Vector3d::UnitY())), 0.0, 1e-13) << "case " << i;
    }
}

TEST(AffineTransform, BoxImageIsTheBoundsOfTheMappedCorners) {
    Rng rng(3);
    const AffineTransform t(testing::randomRotation(rng) * Eigen::Vector3d(1, 2, 3).asDiagonal(),
                            Eigen::Vector3d(4, 5, 6));
    const Eigen::AlignedBox3d box(Point(-1, 0, 2), Point(1, 3, 2.5));
    Eigen::AlignedBox3d corners;
    for (int c = 0; c < 8; ++c) corners.extend(t.apply(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))));
    const Eigen::AlignedBox3d image = t.applyToBox(box);
    EXPECT_TRUE(image.min().isApprox(corners.min(), 1e-13));
    EXPECT_TRUE(image.max().isApprox(corners.max(), 1e-13));
}

}  // namespace
}  // namespace dropscope
