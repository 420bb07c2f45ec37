#include "ImplicitTestSupport.hpp"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace dropscope::testing {
namespace {

std::shared_ptr<const ImplicitBase> blobBase() {
    static const auto base = makeImplicitBase(makeBlob({Point(-0.6, 0, 0), Point(0.7, 0.1, 0)}, {0.8, 0.6}, 0.1));
    return base;
}

TEST(ImplicitBase, MeshIsClosedOnTheSurfaceOutwardAndCounterClockwise) {
    const ImplicitShape shape(blobBase(), AffineTransform(Eigen::Matrix3d(Eigen::Vector3d(1, -2, 0.5).asDiagonal()),
                                                          Eigen::Vector3d(1, 2, 3)));  // reflects
    const SurfaceMesh mesh = shape.mesh();
    ASSERT_GT(mesh.triangles.size(), 2000u);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : mesh.triangles) {
        for (int i = 0; i < 3; ++i) ++edges[{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]}];
        const Point& a = mesh.vertices[t[0]];
        const Eigen::Vector3d n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
        ASSERT_GT(n.dot(mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]]), 0.0);
    }
    // Closed and consistently oriented: each directed edge once, its reverse once.
    for (const auto& [edge, count] : edges) {
        ASSERT_EQ(count, 1);
        ASSERT_EQ(edges.count({edge.second, edge.first}), 1u);
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        ASSERT_EQ(shape.locatePoint(mesh.vertices[i]), PointLocation::OnSurface) << i;
        ASSERT_LT((mesh.normals[i] - shape.normal(mesh.vertices[i]).vector()).norm(), 1e-9) << i;
    }
}

TEST(ImplicitBase, SurfaceCoverContainsTheSurface) {
    const ImplicitShape shape(blobBase(), AffineTransform::rotation(Eigen::Vector3d(1, 1, 0), 0.4));
    const std::vector<Eigen::AlignedBox3d> cover = shape.surfaceCover();
    EXPECT_GE(cover.size(), 100u);
    EXPECT_LE(cover.size(), 5000u);
    const SurfaceMesh mesh = shape.mesh();
    for (std::size_t i = 0; i < mesh.vertices.size(); i += 7) {
        bool covered = false;
        for (const auto& box : cover) covered = covered || box.contains(mesh.vertices[i]);
        ASSERT_TRUE(covered) << i;
    }
    const Eigen::AlignedBox3d bounds = shape.bounds();
    for (const Point& v : mesh.vertices) ASSERT_TRUE(bounds.contains(v));
}

TEST(ImplicitBase, TransformedShapeScalesTheBase) {
    const ImplicitShape base(blobBase(), AffineTransform());
    const AffineTransform similarity(2.0 * AffineTransform::rotation(Eigen::Vector3d(0, 1, 1), 1.0).matrix(),
                                     Eigen::Vector3d(-3, 1, 2));
    const ImplicitShape placed(blobBase(), similarity);
    EXPECT_NEAR(placed.volume(), 8.0 * base.volume(), 1e-12 * placed.volume());
    EXPECT_NEAR(placed.surfaceArea(), 4.0 * base.surfaceArea(), 1e-12 * placed.surfaceArea());
    // A pure translation moves the extremes by r0 exactly (same branch and bound).
    const ImplicitShape moved(blobBase(), AffineTransform::translation(Eigen::Vector3d(1, -2, 3)));
    EXPECT_NEAR(moved.xMin(), base.xMin() + 1, 1e-12);
    EXPECT_NEAR(moved.yMax(), base.yMax() - 2, 1e-12);
    EXPECT_NEAR(moved.zMax(), base.zMax() + 3, 1e-12);
    // A stretched copy: the line-integral area agrees with the area of the stretched mesh.
    const ImplicitShape stretched(blobBase(), AffineTransform::scaling(Eigen::Vector3d(1.5, 1.0, 0.7)));
    const SurfaceMesh mesh = stretched.mesh();
    double meshArea = 0.0;
    for (const auto& t : mesh.triangles)
        meshArea +=
            0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    EXPECT_NEAR(stretched.surfaceArea(), meshArea, 3e-3 * meshArea);  // the mesh's chordal error ~1e-3
    EXPECT_NEAR(stretched.volume(), 1.05 * base.volume(), 1e-12);
}

TEST(ImplicitBase, CloneSharesTheBaseAndWithTransformKeepsTheMedium) {
    ImplicitShape shape(blobBase(), AffineTransform());
    shape.setMediumId(7);
    const auto copy = shape.clone();
    EXPECT_EQ(&dynamic_cast<const ImplicitShape&>(*copy).function(), &shape.function());
    const auto moved = shape.withTransform(AffineTransform::uniformScaling(2.0));
    EXPECT_EQ(moved->mediumId(), 7u);
    EXPECT_EQ(&dynamic_cast<const ImplicitShape&>(*moved).function(), &shape.function());
    EXPECT_EQ(moved->presetName(), "blob");
    EXPECT_TRUE(std::isnan(shape.distanceToSurface(Point(NAN, 0, 0), Direction(1, 0, 0))));
    EXPECT_TRUE(std::isnan(shape.distanceToSurface(Point(0, 0, 0), Direction::invalid())));
}

}  // namespace
}  // namespace dropscope::testing
