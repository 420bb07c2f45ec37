// ParametricShape and ParametricBase: integrals, extremes, mesh, cover, transforms, print, clone.
#include "geometry/Ellipsoid.hpp"
#include "geometry/parametric/ParametricShape.hpp"
#include "geometry/parametric/ParametricTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace dropscope {
namespace {

using testing::randomMatrix;
using testing::Rng;
using testing::sphereBase;
using testing::torusBase;
using testing::uniform;
constexpr double kPi = std::numbers::pi;

TEST(ParametricBase, SphereIntegralsAndOrientation) {
    const ParametricBase& base = *sphereBase();
    // The preset's r_u x r_v points inward (EllipsoidSurface.hpp): orientation -1.
    EXPECT_EQ(base.orientation(), -1.0);
    EXPECT_NEAR(std::abs(base.signedVolume()), 4.0 / 3.0 * kPi, 1e-9);
    EXPECT_NEAR(base.area(), 4.0 * kPi, 1e-9);
    for (const ExtremeRange& r : base.extremes()) {
        EXPECT_NEAR(r.min, -1.0, 1e-10);
        EXPECT_NEAR(r.max, 1.0, 1e-10);
    }
}

TEST(ParametricBase, TorusIntegralsAndOrientation) {
    const ParametricBase& base = *torusBase();
    EXPECT_EQ(base.orientation(), 1.0);
    EXPECT_NEAR(base.signedVolume(), 2.0 * kPi * kPi * 2.0 * 0.25, 1e-9);  // 2 pi^2 R r^2
    EXPECT_NEAR(base.area(), 4.0 * kPi * kPi * 2.0 * 0.5, 1e-9);           // 4 pi^2 R r
    EXPECT_NEAR(base.extremes()[0].min, -2.5, 1e-10);
    EXPECT_NEAR(base.extremes()[1].max, 2.5, 1e-10);
    EXPECT_NEAR(base.extremes()[2].max, 0.5, 1e-10);
}

TEST(ParametricBase, RejectsNullSurface) { EXPECT_THROW(makeParametricBase(nullptr), std::invalid_argument); }

// Mesh vertices on the surface, unit outward normals, counter-clockwise triangles, none degenerate.
void checkMesh(const ParametricShape& shape, bool isSphere) {
    const SurfaceMesh mesh = shape.mesh();
    ASSERT_GT(mesh.triangles.size(), 4000u);
    ASSERT_EQ(mesh.vertices.size(), mesh.normals.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Point& v = mesh.vertices[i];
        const Eigen::Vector3d& n = mesh.normals[i];
        EXPECT_NEAR(n.norm(), 1.0, 1e-12) << "vertex " << i;
        if (isSphere) {
            EXPECT_NEAR(v.norm(), 1.0, 1e-12) << "vertex " << i;
            EXPECT_GT(n.dot(v), 1.0 - 1e-6) << "vertex " << i;
        } else {
            const Eigen::Vector3d ring = 2.0 * Eigen::Vector3d(v.x(), v.y(), 0.0).normalized();
            EXPECT_NEAR((v - ring).norm(), 0.5, 1e-12) << "vertex " << i;
            EXPECT_GT(n.dot((v - ring).normalized()), 1.0 - 1e-9) << "vertex " << i;
        }
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Point& a = mesh.vertices[tri[0]];
        const Point& b = mesh.vertices[tri[1]];
        const Point& c = mesh.vertices[tri[2]];
        const Eigen::Vector3d face = (b - a).cross(c - a);
        ASSERT_GT(face.norm(), 1e-8) << "degenerate triangle " << t;
        EXPECT_GT(face.dot(mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]]), 0.0)
            << "triangle " << t;
    }
}

TEST(ParametricBase, SphereMeshIsOnTheSurfaceAndOutward) { checkMesh(ParametricShape(sphereBase(), {}), true); }

TEST(ParametricBase, TorusMeshIsOnTheSurfaceAndOutward) { checkMesh(ParametricShape(torusBase(), {}), false); }

TEST(ParametricBase, CoverContainsTheSurface) {
    for (const auto* base : {&sphereBase(), &torusBase()}) {
        const ParametricShape shape(*base, AffineTransform(Eigen::Vector3d(1.0, 2.0, 0.5).asDiagonal().toDenseMatrix(),
                                                           Eigen::Vector3d(3.0, -1.0, 2.0)));
        const std::vector<Eigen::AlignedBox3d> cover = shape.surfaceCover();
        const ParameterDomain dom = shape.surface().domain();
        Rng rng(7);
        for (int i = 0; i < 2000; ++i) {
            const double u = uniform(rng, dom.u0, dom.u1), v = uniform(rng, dom.v0, dom.v1);
            const Point p = shape.transform().apply(shape.surface().point(u, v));
            bool covered = false;
            for (const auto& box : cover) covered = covered || box.contains(p);
            ASSERT_TRUE(covered) << "sample " << i << " at (" << u << ", " << v << ")";
        }
    }
}

// The image of the unit sphere under M r + r0 is the Ellipsoid with matrix (M M^T)^-1 and centre r0.
TEST(ParametricShape, TransformedSphereMatchesEllipsoid) {
    for (int i = 0; i < 12; ++i) {
        Rng rng(100 + static_cast<std::uint64_t>(i));
        const Eigen::Matrix3d m = randomMatrix(rng, i % 2 == 1);
        const Eigen::Vector3d r0 = testing::randomPoint(rng, 5.0);
        const ParametricShape shape(sphereBase(), AffineTransform(m, r0));
        const Ellipsoid reference = Ellipsoid::fromMatrix(r0, (m * m.transpose()).inverse());
        const double tol = 1e-9 * reference.semiAxes().maxCoeff();
        EXPECT_NEAR(shape.xMin(), reference.xMin(), tol) << "case " << i;
        EXPECT_NEAR(shape.xMax(), reference.xMax(), tol) << "case " << i;
        EXPECT_NEAR(shape.yMin(), reference.yMin(), tol) << "case " << i;
        EXPECT_NEAR(shape.yMax(), reference.yMax(), tol) << "case " << i;
        EXPECT_NEAR(shape.zMin(), reference.zMin(), tol) << "case " << i;
        EXPECT_NEAR(shape.zMax(), reference.zMax(), tol) << "case " << i;
        EXPECT_NEAR(shape.volume(), reference.volume(), 1e-9 * reference.volume()) << "case " << i;
        EXPECT_NEAR(shape.surfaceArea(), reference.surfaceArea(), 1e-8 * reference.surfaceArea()) << "case " << i;
        EXPECT_EQ(shape.transform().classification().reflects, i % 2 == 1);
    }
}

TEST(ParametricShape, SimilarityScalesAreaAndVolume) {
    const double k = 1.7;
    Rng rng(3);
    const Eigen::Matrix3d m = k * testing::randomRotation(rng);
    const ParametricShape base(torusBase(), {});
    const ParametricShape scaled(torusBase(), AffineTransform(m, Eigen::Vector3d(1.0, -2.0, 3.0)));
    ASSERT_TRUE(scaled.transform().classification().isSimilarity);
    EXPECT_NEAR(scaled.surfaceArea(), k * k * base.surfaceArea(), 1e-12 * scaled.surfaceArea());
    EXPECT_NEAR(scaled.volume(), k * k * k * base.volume(), 1e-12 * scaled.volume());
    // A scaling along the axes: the extremes are the base's, scaled (seed 000 1.4.1), here with a flip of y.
    const ParametricShape stretched(torusBase(), AffineTransform::scaling({2.0, -3.0, 0.5}));
    EXPECT_NEAR(stretched.xMax(), 5.0, 1e-9);
    EXPECT_NEAR(stretched.yMin(), -7.5, 1e-9);
    EXPECT_NEAR(stretched.zMax(), 0.25, 1e-9);
    EXPECT_NEAR(stretched.volume(), 3.0 * base.volume(), 1e-12 * base.volume());
}

TEST(ParametricShape, ShearedTorusAreaFromEquation168) {
    // A shear along the torus axis (x' = x + 0.3 z) is not a similarity; |det M| = 1.
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    m(0, 2) = 0.3;
    const ParametricShape shape(torusBase(), AffineTransform(m, Eigen::Vector3d::Zero()));
    const ParametricShape base(torusBase(), {});
    EXPECT_NEAR(shape.volume(), base.volume(), 1e-12 * base.volume());
    // Brute-force reference: midpoint rule on |M r_u x M r_v| (smooth and periodic: spectrally accurate).
    const int n = 200;
    double area = 0.0;
    const double h = 2.0 * kPi / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const SurfaceJet jet = shape.surface().jet((i + 0.5) * h, (j + 0.5) * h);
            area += (m * jet.ru).cross(m * jet.rv).norm() * h * h;
        }
    EXPECT_NEAR(shape.surfaceArea(), area, 1e-9 * area);
    EXPECT_GT(shape.surfaceArea(), base.surfaceArea() * 1.001);
}

TEST(ParametricShape, PrintCloneAndWithTransform) {
    ParametricShape torus(torusBase(), AffineTransform::translation({1.0, 2.0, 3.0}));
    torus.setMediumId(4);
    std::ostringstream os;
    torus.print(os);
    EXPECT_EQ(os.str(),
              "parametric torus {major_radius: 2, minor_radius: 0.5} M=[[1, 0, 0], [0, 1, 0], [0, 0, 1]] r0=(1, 2, 3)");
    EXPECT_EQ(torus.kind(), ShapeKind::Parametric);
    EXPECT_EQ(torus.typeName(), "parametric");
    EXPECT_EQ(torus.presetName(), "torus");
    ASSERT_EQ(torus.presetParameters().size(), 2u);
    EXPECT_EQ(torus.presetParameters()[1].values.front(), 0.5);

    const std::unique_ptr<Shape> copy = torus.clone();
    const auto& cloned = dynamic_cast<const ParametricShape&>(*copy);
    EXPECT_EQ(cloned.base(), torus.base());
    EXPECT_EQ(cloned.mediumId(), 4u);
    EXPECT_EQ(cloned.xMax(), torus.xMax());

    const std::unique_ptr<GeneralShape> moved = torus.withTransform(AffineTransform::uniformScaling(2.0));
    const auto& placed = dynamic_cast<const ParametricShape&>(*moved);
    EXPECT_EQ(placed.base(), torus.base());
    EXPECT_EQ(placed.mediumId(), 4u);
    EXPECT_NEAR(placed.xMax(), 5.0, 1e-9);
    EXPECT_NEAR(placed.surfaceArea(), 4.0 * torus.surfaceArea(), 1e-12 * placed.surfaceArea());
    EXPECT_THROW(ParametricShape(nullptr, {}), std::invalid_argument);
}

TEST(ParametricShape, SurfaceBandFollowsSizeAndPlace) {
    const ParametricShape unit(sphereBase(), {});
    // Size: characteristic length (the preset's 2 R) times the smallest singular value.
    EXPECT_DOUBLE_EQ(unit.surfaceBand(), tolerance::surfaceBand(2.0, 1.0));
    const ParametricShape far(sphereBase(), AffineTransform(Eigen::Vector3d(0.5, 1.0, 2.0).asDiagonal().toDenseMatrix(),
                                                            Eigen::Vector3d(100.0, 0.0, 0.0)));
    EXPECT_NEAR(far.surfaceBand(), tolerance::surfaceBand(1.0, 100.5), 1e-20);
}

}  // namespace
}  // namespace dropscope
