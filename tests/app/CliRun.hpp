#pragma once

#include "cli/Cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope::test {

struct CliRun {
    int status;
    std::string out;
    std::string err;
};

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
