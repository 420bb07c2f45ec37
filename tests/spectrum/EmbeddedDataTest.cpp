#include "spectrum/EmbeddedData.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace dropscope {
namespace {

TEST(EmbeddedData, ParsesRowsSkippingCommentsAndTheHeader) {
    const auto rows = parseNumberTable("# source\r\nlambda,value\n400, 1.5\n\n# note\n500,1e-3\r\n", 2, "t.csv");
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0], (std::vector<double>{400.0, 1.5}));
    EXPECT_EQ(rows[1], (std::vector<double>{500.0, 1e-3}));
}

TEST(EmbeddedData, RefusesRowsThatDoNotParseNamingTheLine) {
    try {
        parseNumberTable("h\n400,1\n500,x\n", 2, "t.csv");
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "t.csv line 3: not a number: \"x\"");
    }
    EXPECT_THROW(parseNumberTable("h\n400,1,2\n", 2, "t.csv"), std::runtime_error);
    EXPECT_THROW(parseNumberTable("h\n400,\n", 2, "t.csv"), std::runtime_error);
}

}  // namespace
}  // namespace dropscope
