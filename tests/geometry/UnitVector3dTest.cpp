#include "geometry/Vector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace dropscope {
namespace {

TEST(UnitVector3d, NormalisesOnConstruction) {
    const Direction d(3.0, 0.0, 4.0);
    EXPECT_TRUE(static_cast<bool>(d));
    EXPECT_DOUBLE_EQ(d.x(), 0.6);
    EXPECT_DOUBLE_EQ(d.z(), 0.8);
    EXPECT_NEAR(d.vector().norm(), 1.0, 1e-15);
}

TEST(UnitVector3d, ZeroVectorIsInvalid) {
    const Direction d(0.0, 0.0, 0.0);
    EXPECT_FALSE(static_cast<bool>(d));
    EXPECT_TRUE(std::isnan(d.x()) && std::isnan(d.y()) && std::isnan(d.z()));
}

TEST(UnitVector3d, NonFiniteVectorIsInvalid) {
    EXPECT_FALSE(static_cast<bool>(Direction(std::nan(""), 1.0, 0.0)));
    EXPECT_FALSE(static_cast<bool>(Direction(std::numeric_limits<double>::infinity(), 0.0, 0.0)));
    EXPECT_FALSE(static_cast<bool>(Direction()));
}

TEST(UnitVector3d, TinyAndHugeVectorsStillNormalise) {
    EXPECT_NEAR(Direction(1e-300, 1e-300, 0.0).vector().norm(), 1.0, 1e-15);
    EXPECT_NEAR(Direction(1e300, 0.0, 1e300).vector().norm(), 1.0, 1e-15);
}

TEST(UnitVector3d, NegationStaysUnit) {
    const Direction d = -Direction(1.0, 2.0, 2.0);
    EXPECT_DOUBLE_EQ(d.x(), -1.0 / 3.0);
    EXPECT_DOUBLE_EQ(d.z(), -2.0 / 3.0);
}

}  // namespace
}  // namespace dropscope
