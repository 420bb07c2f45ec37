#pragma once

#include "cli/Cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope::test {

struct CliRun {
    int status;
    std::string out;
    std::string err;
};

// An empty folder of the running test's own ("dropscope-PREFIX-SEED-TEST" in the temporary directory): CTest
// runs tests in parallel, so no two share one.
inline std::filesystem::path freshTestDirectory(const std::string& prefix) {
    const auto* test = ::testing::UnitTest::GetInstance();
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() /
        ("dropscope-" + prefix + "-" + std::to_string(test->random_seed()) + "-" + test->current_test_info()->name());
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    return directory;
}

// Runs `dropscope ARGUMENTS...` in-process through runCli.
inline CliRun runDropscope(const std::vector<std::string>& arguments) {
    std::vector<const char*> argv{"dropscope"};
    for (const std::string& argument : arguments) argv.push_back(argument.c_str());
    std::ostringstream out;
    std::ostringstream err;
    const int status = runCli(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

// Bad input: exit 2 and exactly one line on stderr.
inline void expectOneLineFailure(const CliRun& run) {
    EXPECT_EQ(run.status, kExitBadInput);
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.err.ends_with('\n')) << run.err;
}

}  // namespace dropscope::test
