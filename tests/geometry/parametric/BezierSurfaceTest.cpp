#include "geometry/parametric/BezierAsset.hpp"
#include "geometry/parametric/BezierSurface.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/SurfaceExtremes.hpp"
#include "geometry/parametric/SurfaceIntegrals.hpp"
#include "geometry/parametric/SurfaceTestSupport.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using testing::NumericDerivatives;
using testing::Patches;
using testing::Rng;
using testing::uniform;

constexpr double kPi = std::numbers::pi;
const double kKappa = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);  // the cubic quarter-circle's arm

// A closed net from a meridian profile (rho, z) per row, north to south, times the four cubic
// quarter-circle arcs around z: the usual bicubic sphere when the profile is the quarter-circle.
Patches revolvedNet(const std::vector<std::array<Eigen::Vector2d, 4>>& profile) {
    const std::array<Eigen::Vector2d, 4> arc = {Eigen::Vector2d(1, 0), Eigen::Vector2d(1, kKappa),
                                                Eigen::Vector2d(kKappa, 1), Eigen::Vector2d(0, 1)};
    Patches patches(profile.size(), std::vector<BezierNet>(4));
    for (std::size_t r = 0; r < profile.size(); ++r)
        for (std::size_t c = 0; c < 4; ++c)
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j) {
                    Eigen::Vector2d a = arc[j];
                    for (std::size_t q = 0; q < c; ++q) a = Eigen::Vector2d(-a.y(), a.x());  // quarter turns
                    patches[r][c][i][j] =
                        Point(profile[r][i].x() * a.x(), profile[r][i].x() * a.y(), profile[r][i].y());
                }
    return patches;
}

Patches sphereNet() {
    return revolvedNet(
        {{Eigen::Vector2d(0, 1), Eigen::Vector2d(kKappa, 1), Eigen::Vector2d(1, kKappa), Eigen::Vector2d(1, 0)},
         {Eigen::Vector2d(1, 0), Eigen::Vector2d(1, -kKappa), Eigen::Vector2d(kKappa, -1), Eigen::Vector2d(0, -1)}});
}

// A torus of major radius 2 and tube radius 0.5: four rows of quarter-circles around the tube.
Patches torusNet() {
    std::vector<std::array<Eigen::Vector2d, 4>> profile;
    const std::array<Eigen::Vector2d, 4> arc = {Eigen::Vector2d(1, 0), Eigen::Vector2d(1, kKappa),
                                                Eigen::Vector2d(kKappa, 1), Eigen::Vector2d(0, 1)};
    for (int q = 0; q < 4; ++q) {
        std::array<Eigen::Vector2d, 4> row;
        for (std::size_t i = 0; i < 4; ++i) {
            Eigen::Vector2d a = arc[i];
            for (int t = 0; t < q; ++t) a = Eigen::Vector2d(-a.y(), a.x());
            row[i] = Eigen::Vector2d(2.0, 0.0) + 0.5 * a;
        }
        profile.push_back(row);
    }
    return revolvedNet(profile);
}

// De Casteljau's algorithm on one net (independent of the Bernstein sums): r, r_u and r_v at (s, t).
SurfaceJet deCasteljau(const BezierNet& net, double s, double t) {
    const auto curve = [](std::array<Point, 4> p, double x, Eigen::Vector3d& derivative) {
        for (int level = 3; level >= 1; --level) {
            if (level == 1) derivative = 3.0 * (p[1] - p[0]);
            for (int k = 0; k < level; ++k)
                p[static_cast<std::size_t>(k)] =
                    (1.0 - x) * p[static_cast<std::size_t>(k)] + x * p[static_cast<std::size_t>(k + 1)];
        }
        return p[0];
    };
    std::array<Point, 4> along, alongDerivative;
    for (std::size_t i = 0; i < 4; ++i) {
        Eigen::Vector3d dv;
        along[i] = curve(net[i], t, dv);
        alongDerivative[i] = dv;
    }
    SurfaceJet jet;
    jet.r = curve(along, s, jet.ru);
    Eigen::Vector3d unused;
    jet.rv = curve(alongDerivative, s, unused);
    return jet;
}

// The sphere net with its inner control points moved at random: still closed, no longer a sphere.
Patches wobblyNet(Rng& rng) {
    Patches patches = sphereNet();
    for (auto& row : patches)
        for (BezierNet& net : row)
            for (std::size_t i = 1; i < 3; ++i)
                for (std::size_t j = 1; j < 3; ++j) net[i][j] += testing::randomPoint(rng, 0.3);
    return patches;
}

TEST(BezierSurface, EvaluationMatchesDeCasteljau) {
    Rng rng(11);
    const Patches patches = wobblyNet(rng);
    const BezierSurface surface(patches);
    EXPECT_EQ(surface.rows(), 2u);
    EXPECT_EQ(surface.columns(), 4u);
    EXPECT_FALSE(surface.periodicInU());
    EXPECT_TRUE(surface.periodicInV());
    for (int i = 0; i < 400; ++i) {
        const double u = uniform(rng, 0.0, 2.0), v = uniform(rng, 0.0, 4.0);
        const auto r = static_cast<std::size_t>(std::min(std::floor(u), 1.0));
        const auto c = static_cast<std::size_t>(std::min(std::floor(v), 3.0));
        const SurfaceJet expected = deCasteljau(patches[r][c], u - static_cast<double>(r), v - static_cast<double>(c));
        const SurfaceJet jet = surface.jet(u, v);
        EXPECT_LT((surface.point(u, v) - expected.r).norm(), 1e-15) << "case " << i;
        EXPECT_LT((jet.r - expected.r).norm(), 1e-15) << "case " << i;
        EXPECT_LT((jet.ru - expected.ru).norm(), 1e-14) << "case " << i;
        EXPECT_LT((jet.rv - expected.rv).norm(), 1e-14) << "case " << i;
    }
}

TEST(BezierSurface, InterpolatesPatchCorners) {
    Rng rng(12);
    const Patches patches = wobblyNet(rng);
    const BezierSurface surface(patches);
    for (std::size_t r = 0; r < 2; ++r)
        for (std::size_t c = 0; c < 4; ++c)
            for (std::size_t i : {0u, 3u})
                for (std::size_t j : {0u, 3u}) {
                    const double u = static_cast<double>(r) + static_cast<double>(i) / 3.0;
                    const double v = static_cast<double>(c) + static_cast<double>(j) / 3.0;
                    EXPECT_LT((surface.point(u, v) - patches[r][c][i][j]).norm(), 1e-15) << r << c << i << j;
                }
}

TEST(BezierSurface, SecondDerivativesMatchTheNumericDefaults) {
    Rng rng(13);
    const BezierSurface surface(wobblyNet(rng));
    const NumericDerivatives numeric(surface);
    for (int i = 0; i < 200; ++i) {
        // Inside a patch, away from the seams the differences would straddle; and the domain's u edges.
        double u = std::floor(uniform(rng, 0.0, 2.0)) + uniform(rng, 0.01, 0.99);
        if (i < 2) u = 2.0 * i;
        const double v = std::floor(uniform(rng, 0.0, 4.0)) + uniform(rng, 0.01, 0.99);
        const SurfaceJet a = surface.jet(u, v), n = numeric.jet(u, v);
        const SurfaceHessians ha = surface.hessians(u, v), hn = numeric.hessians(u, v);
        EXPECT_LT((a.ru - n.ru).norm(), 1e-8) << "case " << i;
        EXPECT_LT((a.rv - n.rv).norm(), 1e-8) << "case " << i;
        EXPECT_LT((ha.ruu - hn.ruu).norm(), 1e-5) << "case " << i;
        EXPECT_LT((ha.ruv - hn.ruv).norm(), 1e-5) << "case " << i;
        EXPECT_LT((ha.rvv - hn.rvv).norm(), 1e-5) << "case " << i;
    }
}

void expectRejected(const Patches& patches, const std::string& message) {
    try {
        BezierSurface surface(patches);
        ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), message);
    }
}

TEST(BezierSurface, RejectsNetsThatDoNotClose) {
    const Patches sphere = sphereNet();
    {
        Patches p = sphere;
        p[1][2][1][0].x() += 1e-3;
        expectRejected(p, "patches[1][2]: its left edge does not meet patches[1][1]'s right edge");
    }
    {
        Patches p = sphere;
        p[0][3][2][3].z() -= 1e-3;
        expectRejected(
            p, "patches[0][0]: its left edge does not meet patches[0][3]'s right edge (the v seam does not close)");
    }
    {
        Patches p = sphere;
        p[1][1][0][1].z() += 1e-3;
        expectRejected(p, "patches[1][1]: its bottom edge does not meet patches[0][1]'s top edge");
    }
    {
        Patches p = sphere;
        p[0][2][0][1].y() += 1e-3;
        expectRejected(p,
                       "patches[0][2]: its bottom edge (u = 0) is neither a single point (a pole) nor "
                       "patches[1][2]'s top edge (u = 2)");
    }
    {
        Patches p = sphere;
        p[1][3][3][2].x() += 1e-3;
        expectRejected(p,
                       "patches[1][3]: its top edge (u = 2) is neither a single point (a pole) nor "
                       "patches[0][3]'s bottom edge (u = 0)");
    }
    {
        Patches p = torusNet();
        p[3][1][3][2].z() += 1e-3;
        expectRejected(p,
                       "patches[0][1]: its bottom edge (u = 0) is neither a single point (a pole) nor "
                       "patches[3][1]'s top edge (u = 4)");
    }
    {
        Patches p = sphere;
        p[0][1][2][2].y() = std::numeric_limits<double>::quiet_NaN();
        expectRejected(p, "patches[0][1]: control point [2][2] is not finite");
    }
    {
        Patches p = sphere;
        p[1].pop_back();
        expectRejected(p, "patches[1] has 3 patches, patches[0] has 4: rows must be equally long");
    }
    expectRejected({}, "patches must hold at least one patch");
    // A gap far below the tolerance (1e-8 of the net's size) is accepted: scene files round to ~10 digits.
    Patches close = sphere;
    close[1][2][1][0].x() += 1e-11;
    EXPECT_NO_THROW(BezierSurface{close});
}

TEST(BezierSurface, TorusNetIsPeriodicInU) {
    const BezierSurface torus(torusNet());
    EXPECT_TRUE(torus.periodicInU());
    // Cubic quarter-circles overshoot the circle by at most 2.7e-4 of its radius.
    const double area = surfaceAreaIntegral(torus, Eigen::Matrix3d::Identity(), 1e-10).value;
    EXPECT_NEAR(area / (4.0 * kPi * kPi * 2.0 * 0.5), 1.0, 2e-3);
    // Rows run counter-clockwise around the tube, columns counter-clockwise about z: r_u x r_v points
    // into the tube, the signed volume is negative.
    const double volume = signedVolumeIntegral(torus, 1e-10).value;
    EXPECT_NEAR(-volume / (2.0 * kPi * kPi * 2.0 * 0.25), 1.0, 2e-3);
}

// The exact volume of a Bezier surface: div(x, 0, 0) = 1, so V = integral of x (y_u z_v - y_v z_u),
// a polynomial of degree <= 8 in each of s, t on every patch: 5-point Gauss-Legendre is exact.
double exactVolume(const BezierSurface& surface) {
    const std::array<double, 5> x = {-0.906179845938663992797626878299, -0.538469310105683091036314420700, 0.0,
                                     0.538469310105683091036314420700, 0.906179845938663992797626878299};
    const std::array<double, 5> w = {0.236926885056189087514264040720, 0.478628670499366468041291514836,
                                     0.568888888888888888888888888889, 0.478628670499366468041291514836,
                                     0.236926885056189087514264040720};
    double volume = 0.0;
    for (std::size_t r = 0; r < surface.rows(); ++r)
        for (std::size_t c = 0; c < surface.columns(); ++c)
            for (std::size_t i = 0; i < 5; ++i)
                for (std::size_t j = 0; j < 5; ++j) {
                    const SurfaceJet jet = surface.jet(static_cast<double>(r) + 0.5 * (1.0 + x[i]),
                                                       static_cast<double>(c) + 0.5 * (1.0 + x[j]));
                    volume += 0.25 * w[i] * w[j] * jet.r.x() * jet.ru.cross(jet.rv).x();
                }
    return volume;
}

TEST(BezierSurface, SphereNetApproximatesTheUnitSphere) {
    const BezierSurface sphere(sphereNet());
    // |r| lies in [1, (1 + 2.73e-4)^2]: each cubic quarter-circle (kappa = 4/3 (sqrt 2 - 1)) keeps within
    // [1, 1 + 2.73e-4] of its radius, and the net is the product of two of them. So the volume is above
    // 4/3 pi by at most (1 + 2.73e-4)^6 - 1 < 1.7e-3; the area is above 4 pi (the surface encloses the
    // ball, and projection onto a convex body never increases area) and, the surface being as close
    // to the sphere in slope as in position, by at most about twice the radial excess: 1.1e-3 (2e-3 used).
    const double volume = signedVolumeIntegral(sphere, 1e-12).value;
    const double area = surfaceAreaIntegral(sphere, Eigen::Matrix3d::Identity(), 1e-12).value;
    std::cout << "bicubic sphere: volume / (4/3 pi) - 1 = " << volume / (4.0 / 3.0 * kPi) - 1.0
              << ", area / (4 pi) - 1 = " << area / (4.0 * kPi) - 1.0 << '\n';
    EXPECT_GT(volume, 4.0 / 3.0 * kPi);
    EXPECT_LT(volume, 4.0 / 3.0 * kPi * 1.0017);
    EXPECT_GT(area, 4.0 * kPi);
    EXPECT_LT(area, 4.0 * kPi * 1.002);
    EXPECT_NEAR(volume / exactVolume(sphere), 1.0, 1e-12);

    const ExtremeRange z = extremeRange(sphere, Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(z.min, -1.0, 1e-12);
    EXPECT_NEAR(z.max, 1.0, 1e-12);
    const ExtremeRange x = extremeRange(sphere, Eigen::Vector3d::UnitX());
    EXPECT_NEAR(x.min, -1.0, 1e-12);
    EXPECT_NEAR(x.max, 1.0, 1e-12);
    // Along the diagonal the quarter-arc passes through the circle (kappa's defining property).
    const ExtremeRange diagonal = extremeRange(sphere, Eigen::Vector3d(1, 1, 0).normalized());
    EXPECT_NEAR(diagonal.max, 1.0, 1e-12);
}

// The extremes of a lumpy closed net along random directions against a dense brute-force sampling.
TEST(BezierSurface, ExtremesMatchBruteForce) {
    Rng rng(21);
    const BezierSurface surface(wobblyNet(rng));
    constexpr int samplesU = 300, samplesV = 600;
    std::vector<Point> samples;
    for (int i = 0; i <= samplesU; ++i)
        for (int j = 0; j < samplesV; ++j) samples.push_back(surface.point(2.0 * i / samplesU, 4.0 * j / samplesV));
    for (int i = 0; i < 20; ++i) {
        const Eigen::Vector3d d = testing::randomDirection(rng).vector();
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const Point& p : samples) {
            lo = std::min(lo, d.dot(p));
            hi = std::max(hi, d.dot(p));
        }
        const ExtremeRange range = extremeRange(surface, d);
        // Never worse than a sample, better by at most what a grid of spacing h misses, ~|r''| h^2.
        EXPECT_LE(range.min, lo + 1e-15) << "case " << i;
        EXPECT_GE(range.min, lo - 2e-4) << "case " << i;
        EXPECT_GE(range.max, hi - 1e-15) << "case " << i;
        EXPECT_LE(range.max, hi + 2e-4) << "case " << i;
    }
}

TEST(BezierSurface, FlattenedDropletAsset) {
    const auto surface = makeBezierSurface(testing::flattenedDropletPatches());
    const auto& bezier = dynamic_cast<const BezierSurface&>(*surface);
    EXPECT_EQ(bezier.rows(), 2u);
    EXPECT_EQ(bezier.columns(), 4u);
    EXPECT_EQ(surface->presetName(), "bezier");
    EXPECT_EQ(surface->presetParameters()[0].extents, (std::vector<std::size_t>{2, 4, 4, 4, 3}));
    // Rows run from the north pole to the south pole, so r_u x r_v points outward: positive volume,
    // between the squashed lower half-ellipsoid plus upper hemisphere and the unit sphere.
    const QuadratureResult volume = signedVolumeIntegral(*surface, 1e-12);
    EXPECT_GT(volume.value, 2.0 / 3.0 * kPi * 1.6);
    EXPECT_LT(volume.value, 4.0 / 3.0 * kPi);
    EXPECT_NEAR(volume.value / exactVolume(bezier), 1.0, 1e-12);
    // The underside: the south pole at z = -0.6, the last meridian arm flat on that plane.
    const ExtremeRange z = extremeRange(*surface, Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(z.min, -0.6, 1e-12);
    EXPECT_NEAR(z.max, 1.0, 1e-12);
    const ExtremeRange x = extremeRange(*surface, Eigen::Vector3d::UnitX());
    EXPECT_NEAR(x.min, -1.0, 1e-12);
    EXPECT_NEAR(x.max, 1.0, 1e-12);
}

}  // namespace
}  // namespace dropscope
