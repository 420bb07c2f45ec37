#include "ImplicitTestSupport.hpp"

#include "geometry/implicit/Blob.hpp"
#include "geometry/implicit/RayRootFinder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dropscope::testing {
namespace {

// The nearest positive hit of a union of disjoint spheres, by the seed's rules per sphere.
double unionDistance(const Sphere& a, const Sphere& b, const Point& p, const Direction& d) {
    const double da = a.distanceToSurface(p, d);
    const double db = b.distanceToSurface(p, d);
    if (std::isnan(da)) return db;
    if (std::isnan(db)) return da;
    return std::min(da, db);
}

TEST(Blob, FarApartDropletsWithATinyBlendAreTwoSpheres) {
    const Point c0(0, 0, 0);
    const Point c1(2.2, 0.5, -0.3);  // a gap of ~0.58: 580 blend lengths
    const Sphere s0(c0, 1.0);
    const Sphere s1(c1, 0.7);
    const auto base = makeImplicitBase(makeBlob({c0, c1}, {1.0, 0.7}, 1e-3));
    const ImplicitShape blob(base, AffineTransform());
    Rng rng(21);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Point p = randomPoint(rng, 2.5, Point(1.1, 0.25, -0.15));
        const Direction d = i % 2 ? randomDirection(rng) : Direction((i % 4 ? c0 : c1) - p + randomPoint(rng, 0.5));
        const PointLocation expectedLocation =
            s0.locatePoint(p) == PointLocation::Outside ? s1.locatePoint(p) : s0.locatePoint(p);
        ASSERT_EQ(blob.locatePoint(p), expectedLocation) << i;
        const double expected = unionDistance(s0, s1, p, d);
        const double actual = blob.distanceToSurface(p, d);
        ASSERT_EQ(std::isnan(expected), std::isnan(actual)) << i << ": " << expected << " vs " << actual;
        if (!std::isnan(expected)) {
            ++hits;
            ASSERT_NEAR(actual, expected, 1e-8) << i;
            const Point q = p + actual * d.vector();
            const Sphere& hit = s0.locatePoint(q) == PointLocation::OnSurface ? s0 : s1;
            ASSERT_LT((blob.normal(q).vector() - hit.normal(q).vector()).norm(), 1e-8) << i;
        }
    }
    EXPECT_GT(hits, 500);
    const IntegralEstimate volume = blob.volumeEstimate();
    EXPECT_NEAR(volume.value, s0.volume() + s1.volume(), volume.errorEstimate);
    EXPECT_LT(volume.errorEstimate, 2e-2 * volume.value);
    const IntegralEstimate area = blob.areaEstimate();
    EXPECT_NEAR(area.value, s0.surfaceArea() + s1.surfaceArea(), area.errorEstimate);
}

// Every sign change of g along a densely sampled ray is one of the root finder's crossings.
void expectNoMissedCrossing(const ImplicitFunction& f, const Point& origin, const Direction& d, double band,
                            const std::string& where) {
    const double length = 6.0;
    const std::vector<RayCrossing> crossings =
        findRayCrossings(f, origin, d.vector(), 0.0, length, tolerance::implicit::kMinStepBands * band,
                         tolerance::implicit::kRefineBands * band);
    constexpr int kSamples = 20000;
    const double h = length / kSamples;
    std::vector<double> sampled;
    double previous = f.value(origin);
    for (int i = 1; i <= kSamples; ++i) {
        const double g = f.value(origin + i * h * d.vector());
        if ((g < 0.0) != (previous < 0.0)) sampled.push_back((i - 0.5) * h);
        previous = g;
    }
    ASSERT_EQ(crossings.size(), sampled.size()) << where;
    for (std::size_t i = 0; i < sampled.size(); ++i) {
        ASSERT_NEAR(crossings[i].t, sampled[i], h) << where << " crossing " << i;
        ASSERT_NEAR(f.value(origin + crossings[i].t * d.vector()), 0.0, band) << where;
    }
}

TEST(Blob, RootFinderMissesNoCrossingOfOverlappingDroplets) {
    const auto f = makeBlob({Point(-0.6, 0, 0), Point(0.7, 0.1, 0)}, {0.8, 0.6}, 0.1);
    const double band = makeImplicitBase(f)->band();
    Rng rng(31);
    for (int i = 0; i < 200; ++i) {
        const Point origin = randomPoint(rng, 3.0);
        const Direction d(randomPoint(rng, 0.8) - origin);
        expectNoMissedCrossing(*f, origin, d, band, "ray " + std::to_string(i));
    }
}

TEST(Blob, ThinNeckIsFoundAlongRaysThroughIt) {
    // Two droplets just apart, bridged by the blend: a neck a few per cent of the radius wide.
    const Point c0(-1.005, 0, 0);
    const Point c1(1.005, 0, 0);
    const auto f = makeBlob({c0, c1}, {1.0, 1.0}, 0.02);
    ASSERT_LT(f->value(Point::Zero()), 0.0);  // the neck is there
    const double band = makeImplicitBase(f)->band();
    Rng rng(41);
    for (int i = 0; i < 100; ++i) {
        // Rays crossing the neck region across the x axis.
        const Point target(uniform(rng, -0.02, 0.02), uniform(rng, -0.05, 0.05), uniform(rng, -0.05, 0.05));
        const Point origin =
            target + 3.0 * Eigen::Vector3d(uniform(rng, -0.2, 0.2), 1.0, uniform(rng, -1, 1)).normalized();
        expectNoMissedCrossing(*f, origin, Direction(target - origin), band, "neck ray " + std::to_string(i));
    }
}

TEST(Blob, BoundsContainTheSurfaceAndLipschitzBoundHolds) {
    const Blob f({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1.2, 0)}, {0.5, 0.4, 0.3}, 0.2);
    Rng rng(51);
    for (int i = 0; i < 2000; ++i) {
        const Point r = randomPoint(rng, 2.0);
        const Point s = randomPoint(rng, 2.0);
        ASSERT_LE(std::abs(f.value(r) - f.value(s)), (r - s).norm() * (1 + 1e-12)) << i;
        if (f.value(r) <= 0.0) {
            ASSERT_TRUE(f.bounds().contains(r)) << i;
        }
    }
    EXPECT_NEAR(f.value(Point(0, 0, 0) + Point(1e-9, 0, 0)), f.value(Point(0, 0, 0)), 1e-8);
    EXPECT_TRUE(f.gradient(Point(0, 0, 0)).allFinite());
}

TEST(Blob, BadParametersAreRejected) {
    const Point a(0, 0, 0);
    const Point b(1, 0, 0);
    expectMessage([&] { makeBlob({a}, {1.0}, 0.1); }, "at least 2 centers");
    expectMessage([&] { makeBlob({a, b}, {1.0}, 0.1); }, "radii");
    expectMessage([&] { makeBlob({a, b}, {1.0, -1.0}, 0.1); }, "radii must be finite and > 0");
    expectMessage([&] { makeBlob({a, Point(NAN, 0, 0)}, {1.0, 1.0}, 0.1); }, "centers must be finite");
    expectMessage([&] { makeBlob({a, b}, {1.0, 1.0}, 0.0); }, "blend must be finite and > 0");
}

}  // namespace
}  // namespace dropscope::testing
