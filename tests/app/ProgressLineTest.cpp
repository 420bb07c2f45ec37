#include "cli/ProgressLine.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace dropscope {
namespace {

TEST(ProgressLine, ShowsDoneTotalRateAndTimeLeft) {
    EXPECT_EQ(formatProgress({250000, 1000000, 2.0}),
              "trace: 250000 / 1000000 photons (25.0%), 125000 photons/s, 6 s left");
    EXPECT_EQ(formatProgress({1000, 1000000, 1.0}),
              "trace: 1000 / 1000000 photons (0.1%), 1000 photons/s, 16 min 39 s left");
    EXPECT_EQ(formatProgress({1000, 100000000, 1.0}),
              "trace: 1000 / 100000000 photons (0.0%), 1000 photons/s, 27 h 46 min left");
    EXPECT_EQ(formatProgress({0, 10, 1.0}), "trace: 0 / 10 photons (0.0%), 0 photons/s, time left unknown");
}

TEST(ProgressLine, QuietDuringTheFirstSecond) {
    std::ostringstream terminal;
    ProgressLine line(terminal);
    line.update({10, 100, 0.5});
    line.finish({100, 100, 0.9});
    EXPECT_EQ(terminal.str(), "");
}

TEST(ProgressLine, RewritesInPlaceAndEndsWithANewline) {
    std::ostringstream terminal;
    ProgressLine line(terminal);
    line.update({100000, 1000000, 1.0});
    line.update({200000, 1000000, 2.0});
    line.finish({1000000, 1000000, 5.0});
    const std::string text = terminal.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 3);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
    EXPECT_TRUE(text.starts_with("\rtrace: 100000 / 1000000 photons")) << text;
    EXPECT_TRUE(text.ends_with("(100.0%), 200000 photons/s, 0 s left\n")) << text;
}

TEST(ProgressLine, AShorterLineBlanksTheRestOfTheLongerOne) {
    std::ostringstream terminal;
    ProgressLine line(terminal);
    line.update({1, 1000000000, 1000.0});  // "... 0 photons/s, 277777777 h 46 min left"
    line.update({2, 10, 2.0});
    const std::string text = terminal.str();
    const std::string first = text.substr(1, text.find('\r', 1) - 1);
    const std::string second = text.substr(text.find('\r', 1) + 1);
    EXPECT_EQ(second.size(), first.size()) << text;
    EXPECT_TRUE(second.ends_with(" ")) << text;
}

TEST(ProgressLine, LinesStyleWritesWholeLinesAtMostEveryTenSeconds) {
    std::ostringstream log;
    ProgressLine line(log, ProgressLine::Style::Lines);
    line.update({10, 1000, 0.5});    // quiet
    line.update({20, 1000, 1.0});    // shown
    line.update({100, 1000, 10.9});  // too soon after the last
    line.update({110, 1000, 11.0});  // shown
    line.finish({1000, 1000, 12.0});
    const std::string text = log.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 0) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;
    EXPECT_TRUE(text.starts_with("trace: 20 / 1000 photons")) << text;
    EXPECT_NE(text.find("\ntrace: 110 / 1000 photons"), std::string::npos) << text;
    EXPECT_TRUE(text.ends_with("trace: 1000 / 1000 photons (100.0%), 83 photons/s, 0 s left\n")) << text;
}

TEST(ProgressLine, AStringStreamIsNoTerminal) {
    std::ostringstream err;
    EXPECT_FALSE(isTerminal(err));
}

}  // namespace
}  // namespace dropscope
