// Texts results.h5 declares UTF-8: well-formed sequences pass, every other byte becomes U+FFFD.
#include "results/Utf8Text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dropscope {
namespace {

// `count` replacement characters.
std::string replaced(int count) {
    std::string text;
    for (int k = 0; k < count; ++k) text += "\xEF\xBF\xBD";
    return text;
}

TEST(Utf8Text, WellFormedTextPassesUnchanged) {
    for (const std::string text :
         {"", "scene.json", "caf\xC3\xA9", "\xE2\x82\xAC 5", "\xF0\x9F\x8C\x88", "\xF4\x8F\xBF\xBF"}) {
        EXPECT_EQ(utf8Text(text), text);
    }
}

TEST(Utf8Text, EachByteOutsideAWellFormedSequenceIsReplaced) {
    EXPECT_EQ(utf8Text(std::string("a\xFF") + "b"), "a" + replaced(1) + "b");  // never a UTF-8 byte
    EXPECT_EQ(utf8Text("caf\xE9.json"), "caf" + replaced(1) + ".json");        // Latin-1
    EXPECT_EQ(utf8Text("\xC3"), replaced(1));                                  // cut short
    EXPECT_EQ(utf8Text("\xC0\xAF"), replaced(2));                              // an overlong '/'
    EXPECT_EQ(utf8Text("\xED\xA0\x80"), replaced(3));                          // a surrogate
    EXPECT_EQ(utf8Text("\xF4\x90\x80\x80"), replaced(4));                      // above U+10FFFF
    EXPECT_EQ(utf8Text(std::string("\xE2\x82") + "x"), replaced(2) + "x");     // a sequence broken off
}

}  // namespace
}  // namespace dropscope
