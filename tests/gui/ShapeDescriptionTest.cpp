// How the shape editor shows a preset's parameters and the matrix, read-only (gui/ShapeDescription.hpp).
#include "gui/ShapeDescription.hpp"

#include <gtest/gtest.h>

namespace dropscope::gui {
namespace {

TEST(ShapeDescription, NumbersVectorsAndShortPointListsAreShownWhole) {
    EXPECT_EQ(presetParameterText({"major_radius", {}, {1.5}}), "1.5");
    EXPECT_EQ(presetParameterText({"semi_axes", {3}, {1.0, 0.25, 2.0}}), "(1, 0.25, 2)");
    EXPECT_EQ(presetParameterText({"exponents", {2}, {0.5, 3.0}}), "(0.5, 3)");
    EXPECT_EQ(presetParameterText({"centers", {2, 3}, {0, 0, 0, 1, -2, 0.5}}), "(0, 0, 0), (1, -2, 0.5)");
}

TEST(ShapeDescription, LongListsAreSummarised) {
    EXPECT_EQ(presetParameterText({"centers", {5, 3}, std::vector<double>(15, 0.0)}), "5 points");
    EXPECT_EQ(presetParameterText({"radii", {7}, std::vector<double>(7, 1.0)}), "7 numbers");
    EXPECT_EQ(presetParameterText({"patches", {2, 4, 16, 3}, std::vector<double>(2 * 4 * 16 * 3, 0.0)}),
              "2 x 4 patches");
    EXPECT_EQ(presetParameterText({"patches", {3, 16, 3}, std::vector<double>(3 * 16 * 3, 0.0)}), "3 patches");
    EXPECT_EQ(presetParameterText({"grid", {2, 2}, {1, 2, 3, 4}}), "2 x 2 numbers");
    // Values that do not fill the extents are counted, not indexed past their end.
    EXPECT_EQ(presetParameterText({"broken", {3}, {1.0}}), "1 numbers");
}

TEST(ShapeDescription, MatrixRowByRow) {
    Eigen::Matrix3d m;
    m << 1, 2, 3, 4, 5, 6, 7, 8, 0.125;
    const auto rows = matrixRows(m);
    EXPECT_EQ(rows[0], "(1, 2, 3)");
    EXPECT_EQ(rows[1], "(4, 5, 6)");
    EXPECT_EQ(rows[2], "(7, 8, 0.125)");
}

}  // namespace
}  // namespace dropscope::gui
