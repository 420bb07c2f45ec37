#include "cli/WholeNumber.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

namespace dropscope {
namespace {

TEST(WholeNumber, DigitsAndExactScientificNotation) {
    const std::pair<std::string, std::uint64_t> cases[] = {
        {"0", 0},
        {"7", 7},
        {"1000000", 1000000},
        {"1e6", 1000000},
        {"1E9", 1000000000},
        {"2.5e6", 2500000},
        {"1.50e1", 15},
        {"0.0", 0},
        {"120e-1", 12},
        {"3e+2", 300},
        {"18446744073709551615", 18446744073709551615u},
        {"1.8e19", 18000000000000000000u},
    };
    for (const auto& [text, value] : cases) EXPECT_EQ(parseWholeNumber(text), std::optional(value)) << text;
}

TEST(WholeNumber, RefusesSignsFractionsOverflowAndJunk) {
    for (const std::string text : {"", "-1", "+1", "1.5", "2.55e1", "1e", "e6", "1e-1", "0x10", "1 ", " 1", "1,000",
                                   "18446744073709551616", "1e20", "2e19", "1e9999", "nan", "inf"}) {
        EXPECT_EQ(parseWholeNumber(text), std::nullopt) << text;
    }
}

}  // namespace
}  // namespace dropscope
