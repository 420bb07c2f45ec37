#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dropscope {
namespace {

// a = 1, b = 4, c = 0.5 (seed 1.1 notation)
const Box kBox(Point(1.0, -1.0, 0.0), Point(2.0, 3.0, 0.5));
const Box kUnit(Point(0.0, 0.0, 0.0), Point(1.0, 1.0, 1.0));

TEST(Box, ExtremePointsAreTheCorners) {
    EXPECT_EQ(kBox.xMin(), 1.0);
    EXPECT_EQ(kBox.xMax(), 2.0);
    EXPECT_EQ(kBox.yMin(), -1.0);
    EXPECT_EQ(kBox.yMax(), 3.0);
    EXPECT_EQ(kBox.zMin(), 0.0);
    EXPECT_EQ(kBox.zMax(), 0.5);
}

TEST(Box, AreaAndVolumeMatchClosedForms) {
    EXPECT_DOUBLE_EQ(kBox.surfaceArea(), 2.0 * (1.0 * 4.0 + 1.0 * 0.5 + 4.0 * 0.5));
    EXPECT_DOUBLE_EQ(kBox.volume(), 2.0);
}

TEST(Box, RejectsEmptyOrNonFiniteCorners) {
    EXPECT_THROW(Box(Point(0, 0, 0), Point(1, 0, 1)), std::invalid_argument);
    EXPECT_THROW(Box(Point(0, 0, 0), Point(-1, 1, 1)), std::invalid_argument);
    EXPECT_THROW(Box(Point(0, 0, std::nan("")), Point(1, 1, 1)), std::invalid_argument);
}

TEST(Box, LocatesInsideFaceEdgeVertexAndOutside) {
    EXPECT_TRUE(kUnit.encloses(Point(0.5, 0.5, 0.5)));
    EXPECT_TRUE(kUnit.surfaceContains(Point(0.0, 0.5, 0.5)));  // face
    EXPECT_TRUE(kUnit.surfaceContains(Point(1.0, 1.0, 0.5)));  // edge
    EXPECT_TRUE(kUnit.surfaceContains(Point(1.0, 1.0, 1.0)));  // vertex
    EXPECT_FALSE(kUnit.encloses(Point(1.0, 0.5, 0.5)));
    EXPECT_FALSE(kUnit.surfaceContains(Point(1.5, 0.5, 0.5)));
    EXPECT_FALSE(kUnit.encloses(Point(1.5, 0.5, 0.5)));
    EXPECT_FALSE(kUnit.surfaceContains(Point(1.0, 1.5, 0.5)));  // on the face's plane, beyond the face
}

TEST(Box, SurfaceBandIsRelativeToSize) {
    const double band = kUnit.surfaceBand();
    EXPECT_GT(band, 0.0);
    EXPECT_LT(band, 1e-8);
    EXPECT_TRUE(kUnit.surfaceContains(Point(1.0 + 0.5 * band, 0.5, 0.5)));
    EXPECT_FALSE(kUnit.surfaceContains(Point(1.0 + 2.0 * band, 0.5, 0.5)));
    EXPECT_TRUE(kUnit.encloses(Point(1.0 - 2.0 * band, 0.5, 0.5)));
}

TEST(Box, DistanceFromInsideAlongAxes) {
    const Point p(0.25, 0.5, 0.75);
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(p, Direction(1, 0, 0)), 0.75);
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(p, Direction(-1, 0, 0)), 0.25);
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(p, Direction(0, 0, 1)), 0.25);
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(p, Direction(0, -1, 0)), 0.5);
}

TEST(Box, DistanceFromInsideDiagonal) {
    const Point p(0.5, 0.5, 0.5);
    EXPECT_NEAR(kUnit.distanceToSurface(p, Direction(1, 1, 0)), 0.5 * std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(kUnit.distanceToSurface(p, Direction(1, 1, 1)), 0.5 * std::sqrt(3.0), 1e-15);
}

TEST(Box, DistanceFromOutsideHitsTheNearFace) {
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(Point(-2.0, 0.5, 0.5), Direction(1, 0, 0)), 2.0);
    // plane x = 0 is reached at y = 1.5, outside the face (seed eqs. 1.2-1.3); the face y = 1 is not
    // reached either: a miss.
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 0.5, 0.5), Direction(1, 1, 0))));
    // entering through the top face y = 1 at x = 0.5
    EXPECT_NEAR(kUnit.distanceToSurface(Point(-0.5, 2.0, 0.5), Direction(1, -1, 0)), std::sqrt(2.0), 1e-15);
}

TEST(Box, DistanceFromOutsideMovingAwayIsNaN) {
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-2.0, 0.5, 0.5), Direction(-1, 0, 0))));
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-2.0, 0.5, 0.5), Direction(0, 1, 0))));
}

TEST(Box, RayParallelToAFaceOutsideTheSlabMisses) {
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 1.5, 0.5), Direction(1, 0, 0))));
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 0.5, -0.1), Direction(1, 0, 0))));
}

TEST(Box, RaySlidingAlongAFaceOnlyTouches) {
    // along the plane y = 0, which holds the face: touching, never entering
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 0.0, 0.5), Direction(1, 0, 0))));
    // along the edge y = 0, z = 0
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 0.0, 0.0), Direction(1, 0, 0))));
}

TEST(Box, RayThroughAnEdgeOnlyTouches) {
    // crosses the edge x = 0, y = 1 and nothing else
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(-1.0, 0.0, 0.5), Direction(1, 1, 0))));
}

TEST(Box, OnSurfaceLeavingGivesZero) {
    const Point onFace(1.0, 0.5, 0.5);
    EXPECT_EQ(kUnit.distanceToSurface(onFace, Direction(1, 0, 0)), 0.0);
    EXPECT_EQ(kUnit.distanceToSurface(onFace, Direction(1, 1, 0)), 0.0);
    EXPECT_EQ(kUnit.distanceToSurface(onFace, Direction(0, 1, 0)), 0.0);  // tangent: goes on unchanged
}

TEST(Box, OnSurfaceEnteringGivesTheFarSide) {
    EXPECT_DOUBLE_EQ(kUnit.distanceToSurface(Point(1.0, 0.5, 0.5), Direction(-1, 0, 0)), 1.0);
    EXPECT_NEAR(kUnit.distanceToSurface(Point(1.0, 0.5, 0.5), Direction(-1, 1, 0)), 0.5 * std::sqrt(2.0), 1e-15);
    // from an edge into the box along the face diagonal
    EXPECT_NEAR(kUnit.distanceToSurface(Point(0.0, 0.0, 0.5), Direction(1, 1, 0)), std::sqrt(2.0), 1e-15);
    // from an edge, sliding along one of its faces: leaving (tangent)
    EXPECT_EQ(kUnit.distanceToSurface(Point(0.0, 0.0, 0.5), Direction(1, 0, 0)), 0.0);
}

TEST(Box, NaNInputsGiveNaN) {
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(0.5, 0.5, 0.5), Direction(0, 0, 0))));
    EXPECT_TRUE(std::isnan(kUnit.distanceToSurface(Point(std::nan(""), 0.5, 0.5), Direction(1, 0, 0))));
    EXPECT_FALSE(kUnit.surfaceContains(Point(std::nan(""), 0.5, 0.5)));
}

TEST(Box, NormalOnEachFace) {
    EXPECT_EQ(kUnit.normal(Point(0.0, 0.5, 0.5)).vector(), Eigen::Vector3d(-1, 0, 0));
    EXPECT_EQ(kUnit.normal(Point(1.0, 0.5, 0.5)).vector(), Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(kUnit.normal(Point(0.5, 0.0, 0.5)).vector(), Eigen::Vector3d(0, -1, 0));
    EXPECT_EQ(kUnit.normal(Point(0.5, 1.0, 0.5)).vector(), Eigen::Vector3d(0, 1, 0));
    EXPECT_EQ(kUnit.normal(Point(0.5, 0.5, 0.0)).vector(), Eigen::Vector3d(0, 0, -1));
    EXPECT_EQ(kUnit.normal(Point(0.5, 0.5, 1.0)).vector(), Eigen::Vector3d(0, 0, 1));
}

TEST(Box, NoNormalOnEdgesVerticesOrOffTheSurface) {
    EXPECT_FALSE(kUnit.normal(Point(1.0, 1.0, 0.5)));
    EXPECT_FALSE(kUnit.normal(Point(0.0, 0.0, 0.0)));
    EXPECT_FALSE(kUnit.normal(Point(0.5, 0.5, 0.5)));
    EXPECT_FALSE(kUnit.normal(Point(2.0, 0.5, 0.5)));
}

TEST(Box, EnclosesShapesTouchingAllowed) {
    EXPECT_TRUE(kUnit.encloses(Sphere(Point(0.5, 0.5, 0.5), 0.25)));
    EXPECT_TRUE(kUnit.encloses(Sphere(Point(0.5, 0.5, 0.5), 0.5)));  // touches all six faces
    EXPECT_FALSE(kUnit.encloses(Sphere(Point(0.5, 0.5, 0.5), 0.6)));
    EXPECT_TRUE(kUnit.encloses(kUnit));
    EXPECT_FALSE(kUnit.encloses(kBox));
    EXPECT_TRUE(kUnit.encloses(Ellipsoid::fromSemiAxes(Point(0.5, 0.5, 0.5), Eigen::Vector3d(0.5, 0.2, 0.1))));
}

TEST(Box, Prints) {
    std::ostringstream os;
    os << kUnit;
    EXPECT_EQ(os.str(), "Box(min=(0, 0, 0), max=(1, 1, 1))");
}

}  // namespace
}  // namespace dropscope
