#include "geometry/Ellipsoid.hpp"
#include "geometry/parametric/EllipsoidSurface.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/SurfaceTestSupport.hpp"
#include "geometry/parametric/TorusSurface.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dropscope {
namespace {

using testing::NumericDerivatives;
using testing::Rng;
using testing::uniform;

constexpr double kPi = std::numbers::pi;

// Largest deviation of the analytic derivatives from the numeric ones at (u, v), relative to `scale`.
struct DerivativeErrors {
    double first;
    double second;
};
DerivativeErrors compareDerivatives(const ParametricSurface& s, double u, double v, double scale) {
    const NumericDerivatives numeric(s);
    const SurfaceJet a = s.jet(u, v), n = numeric.jet(u, v);
    const SurfaceHessians ha = s.hessians(u, v), hn = numeric.hessians(u, v);
    const double first = std::max({(a.r - n.r).norm(), (a.ru - n.ru).norm(), (a.rv - n.rv).norm()}) / scale;
    const double second =
        std::max({(ha.ruu - hn.ruu).norm(), (ha.ruv - hn.ruv).norm(), (ha.rvv - hn.rvv).norm()}) / scale;
    return {first, second};
}

TEST(EllipsoidSurface, PointsSatisfyTheEllipsoidEquation) {
    const Eigen::Vector3d axes(1.7, 0.9, 0.35);
    const auto surface = makeEllipsoidSurface(axes);
    const Ellipsoid reference = Ellipsoid::fromSemiAxes(Point::Zero(), axes);
    Rng rng(1234);
    for (int i = 0; i < 500; ++i) {
        const double u = i < 2 ? (i == 0 ? -1.0 : 1.0) : uniform(rng, -1.0, 1.0);
        const double v = uniform(rng, 0.0, 2.0 * kPi);
        const Point p = surface->point(u, v);
        const double q = (p.array() / axes.array()).square().sum();
        EXPECT_NEAR(q, 1.0, 1e-15) << "case " << i;
        EXPECT_NEAR(reference.quadraticForm(p), 1.0, 1e-15) << "case " << i;
        EXPECT_EQ(reference.locatePoint(p), PointLocation::OnSurface) << "case " << i;
        EXPECT_EQ(p, surface->jet(u, v).r) << "case " << i;
        // Seed 000 1.3.2's parametrisation: r_u x r_v is the inward normal.
        if (std::abs(u) < 0.999) {
            const SurfaceJet j = surface->jet(u, v);
            const Direction n(j.ru.cross(j.rv));
            EXPECT_NEAR(n.dot(reference.normal(p)), -1.0, 1e-12) << "case " << i;
        }
    }
    // The seed's octant: u, v in [0, 1] x [0, pi/2] gives non-negative coordinates; poles and equator.
    EXPECT_EQ(surface->point(1.0, 0.3), Point(0.0, 0.0, axes.z()));
    EXPECT_EQ(surface->point(-1.0, 2.0), Point(0.0, 0.0, -axes.z()));
    EXPECT_NEAR((surface->point(0.0, kPi / 2) - Point(0.0, axes.y(), 0.0)).norm(), 0.0, 1e-15);
}

TEST(EllipsoidSurface, PolesHaveFiniteDerivatives) {
    const auto surface = makeEllipsoidSurface(Eigen::Vector3d(1.0, 2.0, 3.0));
    for (const double u : {-1.0, 1.0})
        for (const double v : {0.0, 1.0, 2.0 * kPi}) {
            const SurfaceJet j = surface->jet(u, v);
            const SurfaceHessians h = surface->hessians(u, v);
            EXPECT_TRUE(j.ru.allFinite() && j.rv.allFinite() && h.ruu.allFinite() && h.ruv.allFinite() &&
                        h.rvv.allFinite());
            EXPECT_EQ(j.ru, Eigen::Vector3d(0.0, 0.0, 3.0));
            EXPECT_EQ(j.rv, Eigen::Vector3d::Zero());
        }
}

TEST(TorusSurface, PointsLieOnTheTorusAndNormalsPointOutward) {
    const double major = 2.5, minor = 0.8;
    const auto surface = makeTorusSurface(major, minor);
    Rng rng(99);
    for (int i = 0; i < 300; ++i) {
        const double u = uniform(rng, 0.0, 2.0 * kPi), v = uniform(rng, 0.0, 2.0 * kPi);
        const SurfaceJet j = surface->jet(u, v);
        const double rho = std::hypot(j.r.x(), j.r.y());
        EXPECT_NEAR(std::hypot(rho - major, j.r.z()), minor, 1e-15) << "case " << i;
        // Outward: away from the tube's centre circle.
        const Point center(major * j.r.x() / rho, major * j.r.y() / rho, 0.0);
        EXPECT_NEAR(Direction(j.ru.cross(j.rv)).dot(Direction(j.r - center)), 1.0, 1e-13) << "case " << i;
    }
    EXPECT_TRUE(surface->periodicInU() && surface->periodicInV());
    EXPECT_NEAR((surface->point(0.0, 0.3) - surface->point(2.0 * kPi, 0.3)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((surface->point(0.3, 0.0) - surface->point(0.3, 2.0 * kPi)).norm(), 0.0, 1e-15);
}

TEST(ParametricSurface, AnalyticDerivativesMatchTheNumericDefaults) {
    const auto ellipsoid = makeEllipsoidSurface(Eigen::Vector3d(1.3, 0.6, 0.9));
    const auto torus = makeTorusSurface(3.0, 1.1);
    Rng rng(7);
    double worstFirst = 0.0, worstSecond = 0.0;
    for (int i = 0; i < 200; ++i) {
        // Away from the ellipsoid's poles: the differences' truncation error grows like (1 - u^2)^(-7/2).
        const DerivativeErrors e = compareDerivatives(*ellipsoid, uniform(rng, -0.7, 0.7), uniform(rng, 0.0, 2.0 * kPi),
                                                      ellipsoid->characteristicLength());
        // The torus anywhere, its domain's edges included (the stencils wrap around).
        const double u = i < 4 ? (i % 2) * 2.0 * kPi : uniform(rng, 0.0, 2.0 * kPi);
        const double v = i < 4 ? (i / 2) * 2.0 * kPi : uniform(rng, 0.0, 2.0 * kPi);
        const DerivativeErrors t = compareDerivatives(*torus, u, v, torus->characteristicLength());
        EXPECT_LT(e.first, 1e-9) << "ellipsoid case " << i;
        EXPECT_LT(e.second, 1e-6) << "ellipsoid case " << i;
        EXPECT_LT(t.first, 1e-9) << "torus case " << i;
        EXPECT_LT(t.second, 1e-6) << "torus case " << i;
        worstFirst = std::max({worstFirst, e.first, t.first});
        worstSecond = std::max({worstSecond, e.second, t.second});
    }
    std::cout << "numeric vs analytic derivatives, relative: first " << worstFirst << ", second " << worstSecond
              << '\n';
}

TEST(ParametricSurface, NumericDefaultsStayInsideABoundedDomain) {
    // At and near the ellipsoid's bounded u edges the one-sided stencils must not step past u = +-1
    // (where the profile would be evaluated outside its domain).
    const auto ellipsoid = makeEllipsoidSurface(Eigen::Vector3d(1.0, 1.0, 1.0));
    const NumericDerivatives numeric(*ellipsoid);
    for (const double u : {-1.0, -1.0 + 1e-5, 1.0 - 1e-5, 1.0}) {
        const SurfaceJet j = numeric.jet(u, 0.0);
        const SurfaceHessians h = numeric.hessians(u, 0.0);
        EXPECT_TRUE(j.ru.allFinite() && j.rv.allFinite()) << "u = " << u;
        EXPECT_TRUE(h.ruu.allFinite() && h.ruv.allFinite() && h.rvv.allFinite()) << "u = " << u;
    }
    // r_z = c u is linear, so even the one-sided differences at the poles give its derivative c.
    EXPECT_NEAR(numeric.jet(-1.0, 0.5).ru.z(), 1.0, 1e-9);
    EXPECT_NEAR(numeric.jet(1.0, 0.5).ru.z(), 1.0, 1e-9);
}

TEST(ParametricPresets, NamesAndParameters) {
    const auto sphere = makeSphereSurface(2.5);
    EXPECT_EQ(sphere->presetName(), "sphere");
    ASSERT_EQ(sphere->presetParameters().size(), 1u);
    EXPECT_EQ(sphere->presetParameters()[0].key, "radius");
    EXPECT_TRUE(sphere->presetParameters()[0].extents.empty());
    EXPECT_EQ(sphere->presetParameters()[0].values, std::vector<double>{2.5});
    EXPECT_NEAR(sphere->point(0.0, 0.0).x(), 2.5, 1e-15);

    const auto ellipsoid = makeEllipsoidSurface(Eigen::Vector3d(1.0, 2.0, 3.0));
    EXPECT_EQ(ellipsoid->presetName(), "ellipsoid");
    EXPECT_EQ(ellipsoid->presetParameters()[0].key, "semi_axes");
    EXPECT_EQ(ellipsoid->presetParameters()[0].extents, std::vector<std::size_t>{3});
    EXPECT_EQ(ellipsoid->presetParameters()[0].values, (std::vector<double>{1.0, 2.0, 3.0}));
    EXPECT_DOUBLE_EQ(ellipsoid->characteristicLength(), 6.0);

    const auto torus = makeTorusSurface(2.0, 0.5);
    EXPECT_EQ(torus->presetName(), "torus");
    const auto params = torus->presetParameters();
    ASSERT_EQ(params.size(), 2u);
    EXPECT_EQ(params[0].key, "major_radius");
    EXPECT_EQ(params[0].values, std::vector<double>{2.0});
    EXPECT_EQ(params[1].key, "minor_radius");
    EXPECT_EQ(params[1].values, std::vector<double>{0.5});
}

void expectThrowNaming(const std::function<void()>& f, const std::string& word) {
    try {
        f();
        ADD_FAILURE() << "no exception; expected one naming " << word;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

TEST(ParametricPresets, RejectBadParameters) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const double r : {0.0, -1.0, nan, inf}) expectThrowNaming([&] { makeSphereSurface(r); }, "radius");
    for (const Eigen::Vector3d& a :
         {Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(1, 1, -2), Eigen::Vector3d(nan, 1, 1), Eigen::Vector3d(1, inf, 1)})
        expectThrowNaming([&] { makeEllipsoidSurface(a); }, "semi_axes");
    expectThrowNaming([] { makeTorusSurface(1.0, 1.0); }, "minor_radius");
    expectThrowNaming([] { makeTorusSurface(1.0, 2.0); }, "minor_radius");
    expectThrowNaming([] { makeTorusSurface(1.0, 0.0); }, "minor_radius");
    expectThrowNaming([&] { makeTorusSurface(1.0, nan); }, "minor_radius");
    expectThrowNaming([&] { makeTorusSurface(inf, 1.0); }, "major_radius");
    expectThrowNaming([] { makeBezierSurface({}); }, "at least one patch");
    expectThrowNaming([] { makeBezierSurface({{}}); }, "at least one patch");
}

}  // namespace
}  // namespace dropscope
