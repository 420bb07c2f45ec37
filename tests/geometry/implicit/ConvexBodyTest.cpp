#include "ImplicitTestSupport.hpp"

#include "geometry/implicit/ConvexBody.hpp"
#include "geometry/implicit/Superellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

namespace dropscope::testing {
namespace {

TEST(ConvexBody, RadialExitIsTheGaugeRoot) {
    // For a gauge F, the exit along u is 1 / F(u) exactly; Newton from outside needs one or two steps.
    const Superellipsoid f(Eigen::Vector3d(1.0, 0.7, 0.5), Eigen::Vector2d(0.3, 1.7));
    Rng rng(41);
    for (int i = 0; i < 50; ++i) {
        const Eigen::Vector3d u = randomPoint(rng, 1.0).normalized();
        const double tOut = 2.0 / f.gauge(u);
        const RadialExit exit = radialExit(f, Point::Zero(), u, tOut, 1e-13);
        EXPECT_NEAR(exit.t, 1.0 / f.gauge(u), 1e-12) << "case " << i;
        EXPECT_NEAR(exit.gradient.normalized().dot(f.gradient(exit.t * u).normalized()), 1.0, 1e-9) << "case " << i;
    }
}

TEST(ConvexBody, CostDoesNotDependOnTheExponents) {
    // The line sweeps once took ~10^7 evaluations at exponents 0.3 (lines grazing the flat faces); the
    // radial rule takes ~2 evaluations per node whatever the shape.
    const Eigen::Vector3d semiAxes(0.7, 0.7, 0.7);
    for (double e : {0.1, 0.3, 0.35, 1.0, 2.0}) {
        CountingFunction f(makeSuperellipsoid(semiAxes, Eigen::Vector2d(e, e)));
        const ImplicitBase base(std::make_shared<CountingFunction>(f));
        const auto& counted = static_cast<const CountingFunction&>(base.function());
        const BodyIntegrals integrals = base.integrals();
        EXPECT_LT(counted.evaluations, 200000) << "exponent " << e;
        const double exact = superellipsoidVolume(semiAxes, Eigen::Vector2d(e, e));
        EXPECT_LE(std::abs(integrals.volume.value - exact), integrals.volume.errorEstimate) << "exponent " << e;
        std::printf("exponent %.2f: %ld evaluations\n", e, counted.evaluations);
    }
}

TEST(ConvexBody, SphereAreaAndVolumeOffCenter) {
    // The centre need not be the middle of the bounds: a unit sphere seen from an off-centre point.
    const Superellipsoid f(Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector2d(1.0, 1.0));
    const Eigen::AlignedBox3d bounds(Eigen::Vector3d::Constant(-1.01), Eigen::Vector3d::Constant(1.01));
    const BodyIntegrals integrals = convexBodyIntegrals(f, Point(0.3, -0.5, 0.2), bounds, AffineTransform(), 1e-9,
                                                        tolerance::implicit::kConvexIntegralOrder);
    EXPECT_NEAR(integrals.volume.value, 4.0 / 3.0 * std::numbers::pi, 1e-6);
    EXPECT_NEAR(integrals.area.value, 4.0 * std::numbers::pi, 1e-6);
    EXPECT_LE(std::abs(integrals.volume.value - 4.0 / 3.0 * std::numbers::pi), integrals.volume.errorEstimate);
    EXPECT_LE(std::abs(integrals.area.value - 4.0 * std::numbers::pi), integrals.area.errorEstimate);
}

}  // namespace
}  // namespace dropscope::testing
