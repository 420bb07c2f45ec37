#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/SurfaceExtremes.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

namespace dropscope {
namespace {

using testing::Rng;
using testing::uniform;

// Seed 000 eqs. 1.64-1.66 with M = Q: the placed surface Q r(u, v) has its x extremes at
// extremeRange(surface, Q.row(0)); the rotated Ellipsoid's are analytic (seed eqs. 1.27-1.29).
void expectEllipsoidExtremes(const Eigen::Vector3d& axes, const Eigen::Matrix3d& rotation, const std::string& label) {
    const auto surface = makeEllipsoidSurface(axes);
    const Ellipsoid reference = Ellipsoid::fromSemiAxes(Point::Zero(), axes, rotation);
    const double lows[] = {reference.xMin(), reference.yMin(), reference.zMin()};
    const double highs[] = {reference.xMax(), reference.yMax(), reference.zMax()};
    for (int k = 0; k < 3; ++k) {
        const ExtremeRange range = extremeRange(*surface, rotation.row(k).transpose());
        const double scale = highs[k];
        EXPECT_NEAR(range.min / scale, lows[k] / scale, 1e-12) << label << " axis " << k;
        EXPECT_NEAR(range.max / scale, highs[k] / scale, 1e-12) << label << " axis " << k;
    }
}

TEST(SurfaceExtremes, EllipsoidMatchesTheAnalyticExtremes) {
    // Axis-aligned: the z extremes are the poles (u = -1, 1, degenerate in v), x and y on the equator.
    expectEllipsoidExtremes(Eigen::Vector3d(1.5, 0.8, 0.3), Eigen::Matrix3d::Identity(), "identity");
    // Barely rotated: the extremes sit a hair off the poles, where sqrt(1 - u^2) is steepest.
    for (const double angle : {1e-9, 1e-6, 1e-3})
        expectEllipsoidExtremes(Eigen::Vector3d(1.5, 0.8, 0.3), rotationAboutAxis(Direction(1, 2, 0), angle),
                                "small angle " + std::to_string(angle));
    Rng rng(31);
    for (int i = 0; i < 40; ++i) {
        const Eigen::Vector3d axes(uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0), uniform(rng, 0.1, 2.0));
        expectEllipsoidExtremes(axes, testing::randomRotation(rng), "case " + std::to_string(i));
    }
}

TEST(SurfaceExtremes, TorusAlongAnyDirection) {
    // max of d . r over the torus: R |d_xy| + r |d| (the tube's circle around its centre circle).
    const double major = 2.0, minor = 0.6;
    const auto torus = makeTorusSurface(major, minor);
    Rng rng(8);
    for (int i = 0; i < 40; ++i) {
        const Eigen::Vector3d d = i == 0   ? Eigen::Vector3d(0, 0, 1)
                                  : i == 1 ? Eigen::Vector3d(1, 0, 0)
                                           : uniform(rng, 0.1, 3.0) * testing::randomDirection(rng).vector();
        const double expected = major * std::hypot(d.x(), d.y()) + minor * d.norm();
        const ExtremeRange range = extremeRange(*torus, d);
        EXPECT_NEAR(range.max / expected, 1.0, 1e-12) << "case " << i;
        EXPECT_NEAR(range.min / expected, -1.0, 1e-12) << "case " << i;
    }
}

TEST(SurfaceExtremes, SphereScalesWithTheDirection) {
    const auto sphere = makeSphereSurface(2.0);
    const ExtremeRange range = extremeRange(*sphere, Eigen::Vector3d(3.0, 0.0, 4.0));
    EXPECT_NEAR(range.max, 10.0, 1e-12);
    EXPECT_NEAR(range.min, -10.0, 1e-12);
    const ExtremeRange zero = extremeRange(*sphere, Eigen::Vector3d::Zero());
    EXPECT_EQ(zero.min, 0.0);
    EXPECT_EQ(zero.max, 0.0);
    const ExtremeRange invalid = extremeRange(*sphere, Eigen::Vector3d(std::nan(""), 0.0, 1.0));
    EXPECT_TRUE(std::isnan(invalid.min) && std::isnan(invalid.max));
}

}  // namespace
}  // namespace dropscope
