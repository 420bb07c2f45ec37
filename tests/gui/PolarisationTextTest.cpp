// The path inspector's words for an event's polarisation (gui/PolarisationText.hpp).
#include "gui/PolarisationText.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dropscope::gui {
namespace {

Polarisation light(const StokesVector& stokes) { return {stokes, Eigen::Vector3d::UnitX()}; }

TEST(PolarisationText, TheCellsAreTheStokesVectorAndDolpOrDashes) {
    EXPECT_EQ(stokesCells(light({1.0, -0.6, -1e-17, 0.8})),
              (std::array<std::string, 5>{"1.0000", "-0.6000", "0.0000", "0.8000", "0.600"}));
    EXPECT_EQ(stokesCells(std::nullopt), (std::array<std::string, 5>{"-", "-", "-", "-", "-"}));
}

TEST(PolarisationText, TheSummarySaysWhatTheEllipseShows) {
    EXPECT_EQ(polarisationSummary(light({1.0, 0.0, 0.0, 0.0})), "unpolarised (0 % polarised)");
    EXPECT_EQ(polarisationSummary(light({1.0, 0.004, 0.0, 0.0})), "unpolarised (0.4 % polarised)");
    // Linear at -45 degrees, U = -I, with Q = -0: psi is -45 and no "-0" appears for Q = 0, U = -0.
    EXPECT_EQ(polarisationSummary(light({1.0, 0.0, -0.5, 0.0})), "50.0 % polarised: psi -45.0 deg, linear");
    EXPECT_EQ(polarisationSummary(light({1.0, 0.8, -0.0, 0.0})), "80.0 % polarised: psi 0.0 deg, linear");
    // chi = asin(V / p) / 2 = 15 degrees: b/a = tan 15 degrees, V > 0 right-handed.
    const double v = std::sin(std::numbers::pi / 6.0);
    EXPECT_EQ(polarisationSummary(light({1.0, std::cos(std::numbers::pi / 6.0), 0.0, v})),
              "100.0 % polarised: psi 0.0 deg, b/a 0.268, right-handed");
    EXPECT_EQ(polarisationSummary(light({1.0, 0.0, 0.0, -1.0})),
              "100.0 % polarised: psi 0.0 deg, b/a 1.000, left-handed");
    EXPECT_EQ(polarisationSummary(std::nullopt), "no polarisation: traced with 'none' (Fire panel)");
}

}  // namespace
}  // namespace dropscope::gui
