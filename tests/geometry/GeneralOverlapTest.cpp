// The conservative overlap test of parametric and implicit shapes (geometry/GeneralOverlap.cpp).
#include "geometry/Box.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/Sphere.hpp"
#include "geometry/implicit/ImplicitPresets.hpp"
#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/ParametricShape.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using testing::Rng;

// Torus about z, R = 2, r = 0.5: the tube is the set of points within 0.5 of the circle of radius 2.
ParametricShape torus(const Point& at = Point::Zero()) {
    return {makeParametricBase(makeTorusSurface(2.0, 0.5)), AffineTransform::translation(at)};
}

double tubeDistance(const Point& p) {  // signed distance to the torus above
    return std::hypot(std::hypot(p.x(), p.y()) - 2.0, p.z()) - 0.5;
}

TEST(GeneralOverlap, TorusAgainstSpheres) {
    const ParametricShape ring = torus();
    EXPECT_FALSE(ring.overlaps(Sphere(Point(0, 0, 0), 1.4)));   // in the hole, 0.1 clear of the tube
    EXPECT_TRUE(ring.overlaps(Sphere(Point(2, 0, 0.6), 0.3)));  // dips 0.2 into the tube
    EXPECT_TRUE(ring.overlaps(Sphere(Point(2, 0, 0), 0.1)));    // wholly inside the tube
    EXPECT_TRUE(ring.overlaps(Sphere(Point(0, 0, 0), 5.0)));    // swallows the torus
    EXPECT_FALSE(ring.overlaps(Sphere(Point(0, 0, 3), 1.0)));   // above the hole, 0.5 clear
    EXPECT_FALSE(ring.overlaps(Sphere(Point(10, 0, 0), 1.0)));
    // Symmetric, and against boxes too.
    EXPECT_TRUE(Sphere(Point(2, 0, 0.6), 0.3).overlaps(ring));
    EXPECT_TRUE(ring.overlaps(Box(Point(1.9, -0.1, -0.1), Point(2.1, 0.1, 0.1))));
    EXPECT_FALSE(ring.overlaps(Box(Point(-0.5, -0.5, -0.5), Point(0.5, 0.5, 0.5))));
}

// Never misses an overlap: random spheres that reach at least a little into the tube always overlap;
// spheres clear of it by more than the cover's resolution never do.
TEST(GeneralOverlap, NeverMissesAnOverlapWithRandomSpheres) {
    const ParametricShape ring = torus();
    Rng rng(5);
    int clearRefused = 0;
    for (int i = 0; i < 400; ++i) {
        const Point c = testing::randomPoint(rng, 3.0);
        const double radius = testing::uniform(rng, 0.05, 1.0);
        const double gap = tubeDistance(c) - radius;  // < 0: they overlap (or one holds the other)
        const bool overlaps = ring.overlaps(Sphere(c, radius));
        if (gap < -1e-3) {
            EXPECT_TRUE(overlaps) << "case " << i << " gap " << gap;
        } else if (gap > 0.2 && overlaps) {
            ++clearRefused;
        }
    }
    EXPECT_EQ(clearRefused, 0);
}

TEST(GeneralOverlap, TwoGeneralShapes) {
    const ParametricShape a = torus();
    const ParametricShape linked =
        ParametricShape(makeParametricBase(makeTorusSurface(2.0, 0.5)),
                        AffineTransform::rotation(Eigen::Vector3d(1, 0, 0), 1.5707963267948966)
                            .then(AffineTransform::translation(Eigen::Vector3d(2, 0, 0))));
    EXPECT_FALSE(a.overlaps(linked));  // two links of a chain: interlocked, yet apart
    const ImplicitShape blob(makeImplicitBase(makeBlob({Point(2, 0, 0.9), Point(2, 0, 2)}, {0.5, 0.5}, 0.05)),
                             AffineTransform());
    EXPECT_TRUE(a.overlaps(blob));  // the first ball dips 0.1 into the tube
    EXPECT_TRUE(blob.overlaps(a));
    const ImplicitShape far(makeImplicitBase(makeBlob({Point(2, 0, 1.2), Point(2, 0, 2)}, {0.5, 0.5}, 0.01)),
                            AffineTransform());
    EXPECT_FALSE(a.overlaps(far));  // 0.2 clear
}

// A superellipsoid with small exponents has nearly flat, axis-aligned faces: its cover cells there are
// thin. A box far larger than the shape that cuts into such a face (a substrate under a sessile drop)
// must still be found, though its surface band is thicker than those cells.
TEST(GeneralOverlap, AHugeBoxCuttingAFlatFaceIsFound) {
    const ImplicitShape block(
        makeImplicitBase(makeSuperellipsoid(Eigen::Vector3d(1, 1, 0.6), Eigen::Vector2d(0.2, 0.2))), AffineTransform());
    for (const double depth : {1e1, 1e4, 1e6}) {
        EXPECT_TRUE(block.overlaps(Box(Point(-0.3, -0.3, -depth), Point(0.3, 0.3, -0.5)))) << depth;
        EXPECT_TRUE(Box(Point(-depth, -depth, -depth), Point(depth, depth, -0.55)).overlaps(block)) << depth;
        EXPECT_FALSE(block.overlaps(Box(Point(-depth, -depth, -depth), Point(depth, depth, -0.7)))) << depth;
    }
}

// A blob whose droplets lie far apart is two bodies: one of them inside a sphere is an overlap, whichever
// shape comes first.
TEST(GeneralOverlap, APieceOfABlobInsideAnotherShapeIsFoundInEitherOrder) {
    const ImplicitShape pieces(makeImplicitBase(makeBlob({Point(0, 0, 0), Point(20, 0, 0)}, {1.0, 1.0}, 0.05)),
                               AffineTransform());
    const ParametricShape big(makeParametricBase(makeSphereSurface(5.0)),
                              AffineTransform::translation(Eigen::Vector3d(20, 0, 0)));
    EXPECT_TRUE(big.overlaps(pieces));
    EXPECT_TRUE(pieces.overlaps(big));
    const Sphere sphere(Point(20, 0, 0), 5.0);
    EXPECT_TRUE(sphere.overlaps(pieces));
    EXPECT_TRUE(pieces.overlaps(sphere));
    const ParametricShape apart(makeParametricBase(makeSphereSurface(5.0)),
                                AffineTransform::translation(Eigen::Vector3d(10, 0, 0)));
    EXPECT_FALSE(apart.overlaps(pieces));  // between the droplets, 4 clear of each
    EXPECT_FALSE(pieces.overlaps(apart));
}

}  // namespace
}  // namespace dropscope
