#include "gui/plot/PlotCsv.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace dropscope::gui::plot {
namespace {

Figure sharedX() {
    return {"f",
            "theta (deg)",
            AxisRange{0.0, 180.0},
            {{"I", {{"MC", {0.5, 1.5}, {0.1, 1e-20}}, {"Mie", {0.5, 1.5}, {0.1 + 0.2, 2.0}}}, Scale::Log},
             {"P", {{"ratio", {0.5, 1.5}, {-1.0, std::numeric_limits<double>::quiet_NaN()}}}}}};
}

TEST(PlotCsv, CurvesSharingXGetOneXColumnAndOneColumnEach) {
    const Figure figure = sharedX();
    EXPECT_TRUE(sharesX(figure));
    EXPECT_EQ(plotCsv(figure),
              "theta (deg),MC,Mie,ratio\n"
              "0.5,0.1,0.30000000000000004,-1\n"
              "1.5,1e-20,2,nan\n");
    EXPECT_EQ(plotCsvRows(figure), 2u);
}

TEST(PlotCsv, CurvesWithTheirOwnXAreWrittenInLongForm) {
    const Figure figure{"f", "x", std::nullopt, {{"I", {{"MC", {0.5, 1.5}, {0.1, 1e-20}}, {"Mie", {1.0}, {2.0}}}}}};
    EXPECT_FALSE(sharesX(figure));
    EXPECT_EQ(plotCsv(figure),
              "curve,x,y\n"
              "MC,0.5,0.1\n"
              "MC,1.5,1e-20\n"
              "Mie,1,2\n");
    EXPECT_EQ(plotCsvRows(figure), 3u);
}

TEST(PlotCsv, SamplesPastTheShorterOfXAndYAreNotWritten) {
    const Figure figure{"f", "x", std::nullopt, {{"I", {{"a", {1.0, 2.0, 3.0}, {4.0, 5.0}}}}}};
    EXPECT_EQ(plotCsv(figure), "x,a\n1,4\n2,5\n");
}

TEST(PlotCsv, NamesAreQuotedWhereCsvNeedsItAndTwiceUsedNamesTellTheirSubPlot) {
    const Figure figure{
        "f",
        "angle, in degrees",
        std::nullopt,
        {{"top", {{"MC", {1.0}, {2.0}}, {"say \"hi\"", {1.0}, {3.0}}}}, {"bottom", {{"MC", {1.0}, {4.0}}}}}};
    EXPECT_EQ(plotCsv(figure), "\"angle, in degrees\",top: MC,\"say \"\"hi\"\"\",bottom: MC\n1,2,3,4\n");
}

TEST(PlotCsv, AFigureWithoutCurvesIsAHeaderAlone) {
    EXPECT_EQ(plotCsv(Figure{}), "curve,x,y\n");
    EXPECT_EQ(plotCsvRows(Figure{}), 0u);
}

std::filesystem::path scratch(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("dropscope-plot-csv-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" + name);
}

TEST(PlotCsv, WrittenWholeOrNotAtAll) {
    const std::filesystem::path file = scratch("ok.csv");
    writePlotCsv(sharedX(), file);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), plotCsv(sharedX()));
    std::filesystem::remove(file);

    const std::filesystem::path missing = scratch("no-such-directory") / "plot.csv";
    EXPECT_THROW(writePlotCsv(sharedX(), missing), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(missing.parent_path()));
}

}  // namespace
}  // namespace dropscope::gui::plot
