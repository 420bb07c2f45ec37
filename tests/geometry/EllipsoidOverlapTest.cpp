// Overlap tests with an ellipsoid on one side (engine/geometry/EllipsoidOverlap.cpp), each checked
// against a brute-force reference.
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/RandomGeometry.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

namespace dropscope {
namespace {

using testing::Rng;
using testing::uniform;

constexpr double kPi = std::numbers::pi;

std::string caseName(int i) { return "case " + std::to_string(i); }

// ---------------------------------------------------------------------------------------------
// Brute-force references

// Minimum of `form` over the surface of the ellipsoid center + rotation diag(semiAxes) s, |s| = 1:
// a 400 x 400 grid of polar angles, then a pattern search around the best grid point.
template <class Form>
double surfaceMinimum(const Point& center, const Eigen::Vector3d& semiAxes, const Eigen::Matrix3d& rotation,
                      const Form& form) {
    const Eigen::Matrix3d stretch = rotation * semiAxes.asDiagonal();
    const auto value = [&](double theta, double phi) {
        const Eigen::Vector3d s(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        return form(Point(center + stretch * s));
    };
    constexpr int kGrid = 400;
    constexpr std::array<std::array<double, 2>, 4> kMoves{{{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}};
    const double thetaStep = kPi / kGrid;
    const double phiStep = 2.0 * kPi / kGrid;
    double best = std::numeric_limits<double>::infinity();
    double bestTheta = 0.0;
    double bestPhi = 0.0;
    for (int i = 0; i < kGrid; ++i) {
        const double theta = (i + 0.5) * thetaStep;
        for (int j = 0; j < kGrid; ++j) {
            const double phi = j * phiStep;
            const double q = value(theta, phi);
            if (q < best) {
                best = q;
                bestTheta = theta;
                bestPhi = phi;
            }
        }
    }
    for (double step = thetaStep; step > 1e-13;) {
        bool moved = false;
        for (const auto& [dTheta, dPhi] : kMoves) {
            const double theta = bestTheta + dTheta * step;
            const double phi = bestPhi + dPhi * step;
            const double q = value(theta, phi);
            if (q < best) {
                best = q;
                bestTheta = theta;
                bestPhi = phi;
                moved = true;
            }
        }
        if (!moved) step *= 0.5;
    }
    return best;
}

struct BoxMinimum {
    double value;
    Point at;
};

// Minimum of (x - c).M(x - c) over the box: a 41^3 grid of box points, then cyclic coordinate
// descent with exact line minimisation clamped to the box.
BoxMinimum boxMinimum(const Point& center, const Eigen::Matrix3d& m, const Box& box) {
    const auto form = [&](const Point& x) { return (x - center).dot(m * (x - center)); };
    constexpr int kGrid = 41;
    const Eigen::Vector3d step = box.edgeLengths() / (kGrid - 1);
    BoxMinimum best{std::numeric_limits<double>::infinity(), Point::Zero()};
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            for (int k = 0; k < kGrid; ++k) {
                const Point x = box.lower() + Eigen::Vector3d(i, j, k).cwiseProduct(step);
                const double q = form(x);
                if (q < best.value) best = {q, x};
            }
        }
    }
    Point x = best.at;
    for (int sweep = 0; sweep < 10000; ++sweep) {
        double largestMove = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            const double slope = (m * (x - center))[axis];
            const double target = std::clamp(x[axis] - slope / m(axis, axis), box.lower()[axis], box.upper()[axis]);
            largestMove = std::max(largestMove, std::abs(target - x[axis]));
            x[axis] = target;
        }
        if (largestMove == 0.0) break;
    }
    const double refined = form(x);
    return refined <= best.value ? BoxMinimum{refined, x} : best;
}

// Coordinates of `p` lying on a bound of the box.
int boundCount(const Point& p, const Box& box) {
    int count = 0;
    for (int i = 0; i < 3; ++i) count += p[i] == box.lower()[i] || p[i] == box.upper()[i];
    return count;
}

double vertexMinimum(const Point& center, const Eigen::Matrix3d& m, const Box& box) {
    double minimum = std::numeric_limits<double>::infinity();
    for (int corner = 0; corner < 8; ++corner) {
        Point v;
        for (int i = 0; i < 3; ++i) v[i] = ((corner >> i) & 1) != 0 ? box.upper()[i] : box.lower()[i];
        minimum = std::min(minimum, (v - center).dot(m * (v - center)));
    }
    return minimum;
}

Eigen::Matrix3d randomShapeMatrix(Rng& rng) {
    const Eigen::Vector3d semiAxes(uniform(rng, 0.2, 2.0), uniform(rng, 0.2, 2.0), uniform(rng, 0.2, 2.0));
    const Eigen::Matrix3d rotation = testing::randomRotation(rng);
    return rotation * semiAxes.cwiseAbs2().asDiagonal() * rotation.transpose();
}

// ---------------------------------------------------------------------------------------------
// gilitschenskiMaximum

TEST(GilitschenskiMaximum, TwoSpheresGiveCenterDistanceOverRadiusSumSquared) {
    for (int i = 0; i < 1000; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Point c1 = testing::randomPoint(rng, 10.0);
        const Point c2 = testing::randomPoint(rng, 10.0);
        const double r1 = std::exp(uniform(rng, -3.0, 3.0));
        const double r2 = std::exp(uniform(rng, -3.0, 3.0));
        const double expected = (c2 - c1).squaredNorm() / ((r1 + r2) * (r1 + r2));
        const double actual =
            gilitschenskiMaximum(c1, r1 * r1 * Eigen::Matrix3d::Identity(), c2, r2 * r2 * Eigen::Matrix3d::Identity());
        EXPECT_NEAR(actual, expected, 1e-13 * expected);
    }
}

TEST(GilitschenskiMaximum, IsTheMaximumOfKOverLambda) {
    for (int i = 0; i < 100; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Point c1 = testing::randomPoint(rng, 3.0);
        const Point c2 = testing::randomPoint(rng, 3.0);
        const Eigen::Matrix3d shape1 = randomShapeMatrix(rng);
        const Eigen::Matrix3d shape2 = randomShapeMatrix(rng);
        const Eigen::Vector3d dr = c2 - c1;
        // 1 - K(lambda), seed eq. 1.34, by a direct 3x3 inverse on a fine lambda grid
        double gridMaximum = 0.0;
        constexpr int kGrid = 20000;
        for (int k = 1; k < kGrid; ++k) {
            const double lambda = static_cast<double>(k) / kGrid;
            const Eigen::Matrix3d sum = shape1 / lambda + shape2 / (1.0 - lambda);
            gridMaximum = std::max(gridMaximum, dr.dot(sum.inverse() * dr));
        }
        const double maximum = gilitschenskiMaximum(c1, shape1, c2, shape2);
        EXPECT_LE(gridMaximum, maximum * (1.0 + 1e-12));
        EXPECT_NEAR(maximum, gridMaximum, 1e-7 * maximum);
        EXPECT_EQ(maximum, gilitschenskiMaximum(c2, shape2, c1, shape1));
    }
}

// Needles and plates of semi-axis ratio up to ~1e4 and sizes up to ~1e3 apart, where the maximiser
// comes close to lambda = 0 or 1: a grid in t = ln(lambda / (1 - lambda)), refined by
// golden-section search, of the direct form
// 1 - K = dr . (shapeA (1 + e^{-t}) + shapeB (1 + e^{t}))^{-1} dr.
TEST(GilitschenskiMaximum, MatchesGridSearchForElongatedPairs) {
    for (int i = 0; i < 30; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const auto shape = [&] {
            const double size = std::exp(uniform(rng, -3.5, 3.5));
            const Eigen::Vector3d semiAxes =
                size * Eigen::Vector3d(std::exp(uniform(rng, -4.5, 4.5)), std::exp(uniform(rng, -4.5, 4.5)),
                                       std::exp(uniform(rng, -4.5, 4.5)));
            const Eigen::Matrix3d rotation = testing::randomRotation(rng);
            return Eigen::Matrix3d(rotation * semiAxes.cwiseAbs2().asDiagonal() * rotation.transpose());
        };
        const Eigen::Matrix3d shape1 = shape();
        const Eigen::Matrix3d shape2 = shape();
        const Point c1 = testing::randomPoint(rng, 1.0);
        const Point c2 = c1 + std::exp(uniform(rng, -3.0, 3.0)) * testing::randomDirection(rng).vector();
        const Eigen::Vector3d dr = c2 - c1;
        const auto f = [&](double t) {
            const Eigen::Matrix3d sum = shape1 * (1.0 + std::exp(-t)) + shape2 * (1.0 + std::exp(t));
            return dr.dot(sum.ldlt().solve(dr));
        };
        constexpr int kGrid = 20000;
        constexpr double kRange = 25.0;
        constexpr double kStep = 2.0 * kRange / kGrid;
        double best = -kRange;
        double bestValue = f(best);
        for (int k = 1; k <= kGrid; ++k) {
            const double t = -kRange + k * kStep;
            const double value = f(t);
            if (value > bestValue) {
                best = t;
                bestValue = value;
            }
        }
        double lo = best - kStep;
        double hi = best + kStep;
        const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
        while (hi - lo > 1e-12) {
            const double left = hi - golden * (hi - lo);
            const double right = lo + golden * (hi - lo);
            if (f(left) < f(right)) {
                lo = left;
            } else {
                hi = right;
            }
        }
        const double reference = f(0.5 * (lo + hi));
        EXPECT_NEAR(gilitschenskiMaximum(c1, shape1, c2, shape2), reference, 1e-8 * reference);
    }
}

TEST(GilitschenskiMaximum, IsZeroForCoincidentCenters) {
    Rng rng(7);
    const Point c = testing::randomPoint(rng, 1.0);
    EXPECT_EQ(gilitschenskiMaximum(c, randomShapeMatrix(rng), c, randomShapeMatrix(rng)), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Ellipsoid-ellipsoid and ellipsoid-sphere

// A at a random centre and B displaced along `axis` by `factor` times the sum of the two
// semi-axes along it: both axis-aligned, so they touch at factor = 1.
TEST(EllipsoidOverlap, AxisAlignedPairsTouchAtTheSumOfSemiAxes) {
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const int axis = i % 3;
        const Point centerA = testing::randomPoint(rng, 5.0);
        const Eigen::Vector3d semiA(uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0));
        const Eigen::Vector3d semiB(uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0));
        const double radius = uniform(rng, 0.1, 2.0);
        const Ellipsoid a = Ellipsoid::fromSemiAxes(centerA, semiA);
        const auto displaced = [&](double reach, double factor) {
            Point c = centerA;
            c[axis] += factor * reach;
            return c;
        };
        constexpr std::array<std::pair<double, bool>, 3> kFactors{
            {{1.0, false}, {1.0 - 1e-6, true}, {1.0 + 1e-6, false}}};
        for (const auto& [factor, overlapping] : kFactors) {
            SCOPED_TRACE("factor " + std::to_string(factor));
            const Ellipsoid b = Ellipsoid::fromSemiAxes(displaced(semiA[axis] + semiB[axis], factor), semiB);
            const Sphere s(displaced(semiA[axis] + radius, factor), radius);
            EXPECT_EQ(a.overlaps(b), overlapping);
            EXPECT_EQ(a.overlaps(s), overlapping);
        }
    }
}

// Rotated A against rotated B (or a sphere B), against the brute-force surface minimum.
TEST(EllipsoidOverlap, RotatedPairsMatchBruteForce) {
    int overlapping = 0;
    int separate = 0;
    for (int i = 0; i < 60; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Point centerA = testing::randomPoint(rng, 3.0);
        const Eigen::Vector3d semiA(uniform(rng, 0.3, 1.5), uniform(rng, 0.3, 1.5), uniform(rng, 0.3, 1.5));
        const Eigen::Matrix3d rotationA =
            rotationAboutAxis(testing::randomDirection(rng), uniform(rng, 0.0, 2.0 * kPi));
        const Ellipsoid a = Ellipsoid::fromSemiAxes(centerA, semiA, rotationA);
        const Eigen::Vector3d semiB(uniform(rng, 0.3, 1.5), uniform(rng, 0.3, 1.5), uniform(rng, 0.3, 1.5));
        const double reach = uniform(rng, 0.0, 1.1 * (semiA.maxCoeff() + semiB.maxCoeff()));
        const Point centerB = centerA + reach * testing::randomDirection(rng).vector();
        std::unique_ptr<Shape> b;
        double minimum = 0.0;
        if (i % 3 == 2) {
            const Sphere sphere(centerB, semiB.x());
            minimum = surfaceMinimum(centerA, semiA, rotationA, [&](const Point& x) {
                return (x - centerB).squaredNorm() / (sphere.radius() * sphere.radius());
            });
            b = std::make_unique<Sphere>(sphere);
        } else {
            const Eigen::Matrix3d rotationB =
                rotationAboutAxis(testing::randomDirection(rng), uniform(rng, 0.0, 2.0 * kPi));
            const Ellipsoid ellipsoid = Ellipsoid::fromSemiAxes(centerB, semiB, rotationB);
            minimum =
                surfaceMinimum(centerA, semiA, rotationA, [&](const Point& x) { return ellipsoid.quadraticForm(x); });
            b = std::make_unique<Ellipsoid>(ellipsoid);
        }
        // A's surface enters B, or B lies inside A and so does its centre.
        if (std::abs(std::sqrt(minimum) - 1.0) < 1e-3) continue;  // too close to touching to judge
        const bool expected = minimum < 1.0 || a.quadraticForm(centerB) < 1.0;
        EXPECT_EQ(a.overlaps(*b), expected) << "surface minimum " << minimum;
        ++(expected ? overlapping : separate);
    }
    EXPECT_GE(overlapping, 10);
    EXPECT_GE(separate, 10);
}

TEST(EllipsoidOverlap, IsSymmetric) {
    for (int i = 0; i < 600; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Ellipsoid a = testing::randomEllipsoid(rng, Point::Zero(), 1.0);
        const std::unique_ptr<Shape> b = testing::randomShape(rng, i, Point::Zero(), 1.0);
        EXPECT_EQ(a.overlaps(*b), b->overlaps(a));
    }
    // Touching pairs: the verdict sits on the rounding of the threshold.
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Ellipsoid a = testing::randomEllipsoid(rng, Point::Zero(), 1.0);
        const Ellipsoid b = testing::randomEllipsoid(rng, Point::Zero(), 1.0);
        const double scale =
            std::sqrt(gilitschenskiMaximum(a.center(), a.inverseMatrix(), b.center(), b.inverseMatrix()));
        // Both scaled by sqrt(max f) about their centres (M -> M / max f) touch.
        const Ellipsoid aTouching = Ellipsoid::fromMatrix(a.center(), a.matrix() / (scale * scale));
        const Ellipsoid bTouching = Ellipsoid::fromMatrix(b.center(), b.matrix() / (scale * scale));
        EXPECT_EQ(aTouching.overlaps(bTouching), bTouching.overlaps(aTouching));
        EXPECT_FALSE(aTouching.overlaps(bTouching));
    }
}

// ---------------------------------------------------------------------------------------------
// Ellipsoid-box

TEST(EllipsoidBoxOverlap, MinimumMatchesBruteForceOverBoxPoints) {
    int overlapping = 0;
    int separate = 0;
    for (int i = 0; i < 200; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Box box = testing::randomBox(rng, Point::Zero(), 1.0);
        const Ellipsoid e = testing::randomEllipsoid(rng, box.center(), 1.5);
        const double minimum = minimumQuadraticFormOverBox(e.center(), e.matrix(), box);
        const BoxMinimum reference = boxMinimum(e.center(), e.matrix(), box);
        EXPECT_LE(minimum, reference.value * (1.0 + 1e-12));
        EXPECT_NEAR(minimum, reference.value, 1e-10 * std::max(1.0, reference.value));
        if (std::abs(std::sqrt(reference.value) - 1.0) < 1e-3) continue;
        const bool expected = reference.value < 1.0;
        EXPECT_EQ(e.overlaps(box), expected);
        EXPECT_EQ(box.overlaps(e), expected);
        ++(expected ? overlapping : separate);
    }
    EXPECT_GE(overlapping, 20);
    EXPECT_GE(separate, 20);
}

TEST(EllipsoidBoxOverlap, CenterInsideTheBoxGivesZero) {
    const Box box(Point(0.0, 0.0, 0.0), Point(2.0, 1.0, 3.0));
    for (const Point& c : {Point(1.0, 0.5, 1.5), Point(0.0, 0.0, 0.0), Point(2.0, 0.3, 3.0)}) {
        EXPECT_EQ(minimumQuadraticFormOverBox(c, Eigen::Matrix3d::Identity(), box), 0.0);
    }
}

// The seed's centroid test misses this one: the box centroid, the vertices, the edges and the
// faces are all outside the ellipsoid.
TEST(EllipsoidBoxOverlap, SmallEllipsoidInsideLargeBoxAwayFromItsCentroid) {
    const Box box(Point(0.0, 0.0, 0.0), Point(10.0, 10.0, 10.0));
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(2.0, 3.0, 7.0), Eigen::Vector3d(0.5, 0.3, 0.2),
                                                rotationAboutAxis(Direction(1.0, 2.0, 3.0), 0.7));
    EXPECT_GT(e.quadraticForm(box.center()), 1.0);
    EXPECT_EQ(minimumQuadraticFormOverBox(e.center(), e.matrix(), box), 0.0);
    EXPECT_TRUE(e.overlaps(box));
    EXPECT_TRUE(box.overlaps(e));
}

TEST(EllipsoidBoxOverlap, CrossingOnlyOneEdge) {
    const Box box(Point(0.0, 0.0, 0.0), Point(2.0, 2.0, 2.0));
    // Long axis along (1,1,0), pointing at the edge x = y = 0 and crossing it at z = 1.
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(-0.3, -0.3, 1.0), Eigen::Vector3d(0.8, 0.3, 0.6),
                                                rotationAboutAxis(Direction(0.0, 0.0, 1.0), kPi / 4.0));
    const BoxMinimum reference = boxMinimum(e.center(), e.matrix(), box);
    EXPECT_EQ(boundCount(reference.at, box), 2);  // the closest point is inside an edge
    EXPECT_GT(vertexMinimum(e.center(), e.matrix(), box), 1.0);
    const double minimum = minimumQuadraticFormOverBox(e.center(), e.matrix(), box);
    EXPECT_NEAR(minimum, reference.value, 1e-12);
    EXPECT_LT(minimum, 1.0);
    EXPECT_TRUE(e.overlaps(box));
}

TEST(EllipsoidBoxOverlap, CrossingOnlyOneFaceInterior) {
    const Box box(Point(0.0, 0.0, 0.0), Point(2.0, 2.0, 2.0));
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point(1.2, 0.9, -0.2), Eigen::Vector3d(0.5, 0.4, 0.3),
                                                rotationAboutAxis(Direction(1.0, -1.0, 2.0), 0.4));
    const BoxMinimum reference = boxMinimum(e.center(), e.matrix(), box);
    EXPECT_EQ(boundCount(reference.at, box), 1);  // the closest point is inside a face
    EXPECT_GT(vertexMinimum(e.center(), e.matrix(), box), 1.0);
    const double minimum = minimumQuadraticFormOverBox(e.center(), e.matrix(), box);
    EXPECT_NEAR(minimum, reference.value, 1e-12);
    EXPECT_LT(minimum, 1.0);
    EXPECT_TRUE(e.overlaps(box));

    // Axis-aligned: the closest point is straight above the centre, at Q = (0.2 / 0.3)^2.
    const Ellipsoid aligned = Ellipsoid::fromSemiAxes(e.center(), Eigen::Vector3d(0.5, 0.4, 0.3));
    EXPECT_NEAR(minimumQuadraticFormOverBox(aligned.center(), aligned.matrix(), box), 4.0 / 9.0, 1e-15);
}

TEST(EllipsoidBoxOverlap, TouchingAFaceIsNotOverlapping) {
    const Box box(Point(0.0, 0.0, 0.0), Point(2.0, 2.0, 2.0));
    // Semi-axis 0.5 along z, rotated about z: the lowest point, z = -0.5 + 0.5, touches z = 0.
    const Eigen::Matrix3d rotation = rotationAboutAxis(Direction(0.0, 0.0, 1.0), kPi / 6.0);
    const Eigen::Vector3d semiAxes(0.75, 0.25, 0.5);
    const Ellipsoid touching = Ellipsoid::fromSemiAxes(Point(1.0, 1.0, -0.5), semiAxes, rotation);
    EXPECT_NEAR(minimumQuadraticFormOverBox(touching.center(), touching.matrix(), box), 1.0, 1e-15);
    EXPECT_FALSE(touching.overlaps(box));
    EXPECT_FALSE(box.overlaps(touching));
    const Ellipsoid closer = Ellipsoid::fromSemiAxes(Point(1.0, 1.0, -0.5 * (1.0 - 1e-6)), semiAxes, rotation);
    EXPECT_TRUE(closer.overlaps(box));
    const Ellipsoid further = Ellipsoid::fromSemiAxes(Point(1.0, 1.0, -0.5 * (1.0 + 1e-6)), semiAxes, rotation);
    EXPECT_FALSE(further.overlaps(box));
}

TEST(EllipsoidBoxOverlap, BoxInsideTheEllipsoid) {
    const Box box(Point(0.2, 0.2, 0.2), Point(0.6, 0.7, 0.5));
    const Ellipsoid e = Ellipsoid::fromSemiAxes(Point::Zero(), Eigen::Vector3d(3.0, 2.0, 2.5),
                                                rotationAboutAxis(Direction(2.0, 1.0, -1.0), 1.1));
    const double minimum = minimumQuadraticFormOverBox(e.center(), e.matrix(), box);
    EXPECT_GT(minimum, 0.0);
    EXPECT_NEAR(minimum, boxMinimum(e.center(), e.matrix(), box).value, 1e-12);
    EXPECT_TRUE(e.overlaps(box));
    EXPECT_TRUE(box.overlaps(e));
}

// ---------------------------------------------------------------------------------------------
// Sampled volume: a point strictly inside both shapes proves a positive volume of intersection.

TEST(EllipsoidOverlap, SampledVolumeAgreesWithVerdict) {
    int witnessed = 0;
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE(caseName(i));
        Rng rng(static_cast<Rng::result_type>(i));
        const Ellipsoid a = testing::randomEllipsoid(rng, Point::Zero(), 1.0);
        const std::unique_ptr<Shape> b = testing::randomShape(rng, i, Point::Zero(), 1.0);
        const Point lower(std::max(a.xMin(), b->xMin()), std::max(a.yMin(), b->yMin()), std::max(a.zMin(), b->zMin()));
        const Point upper(std::min(a.xMax(), b->xMax()), std::min(a.yMax(), b->yMax()), std::min(a.zMax(), b->zMax()));
        const bool overlaps = a.overlaps(*b);
        if (!(lower.array() < upper.array()).all()) {
            EXPECT_FALSE(overlaps);  // disjoint bounding boxes
            continue;
        }
        bool insideBoth = false;
        for (int k = 0; k < 2000 && !insideBoth; ++k) {
            const Point p(uniform(rng, lower.x(), upper.x()), uniform(rng, lower.y(), upper.y()),
                          uniform(rng, lower.z(), upper.z()));
            insideBoth = a.encloses(p) && b->encloses(p);
        }
        if (insideBoth) {
            EXPECT_TRUE(overlaps) << a << " and " << *b;
            ++witnessed;
        }
    }
    EXPECT_GE(witnessed, 50);
}

}  // namespace
}  // namespace dropscope
