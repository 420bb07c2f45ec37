// The list of golden cases, tests/golden/cases.txt, as the test and scripts/update-goldens.sh read it.
#include "render/GoldenCases.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace dropscope {
namespace {

TEST(GoldenCaseList, ReadsNamesScenesAndArgumentsAndRejectsBadLines) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("dropscope-golden-cases-" + std::to_string(::getpid()) + ".txt");
    std::ofstream(file) << "# comment\n\nfirst  a.json  --width 32 --height 16\nsecond b.json\nthird ../c.json\n";
    const std::vector<test::GoldenCase> cases = test::readGoldenCases(file);
    ASSERT_EQ(cases.size(), 3u);
    EXPECT_EQ(cases[2].scene, "../c.json");
    EXPECT_EQ(cases[0].name, "first");
    EXPECT_EQ(cases[0].scene, "a.json");
    EXPECT_EQ(cases[0].arguments, (std::vector<std::string>{"--width", "32", "--height", "16"}));
    EXPECT_TRUE(cases[1].arguments.empty());
    for (const char* bad : {"first a.json\nfirst b.json\n", "bad-name a.json\n", "name\n", "name dir/a.json\n",
                            "name ../dir/a.json\n", "name ../../a.json\n", "name .json\n"}) {
        std::ofstream(file) << bad;
        EXPECT_THROW(test::readGoldenCases(file), std::runtime_error) << bad;
    }
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace dropscope
