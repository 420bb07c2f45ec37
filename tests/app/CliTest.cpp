// The top level of the dropscope command line: commands, help, and bad arguments.
#include "app/CliRun.hpp"
#include "cli/Cli.hpp"
#include "results/Version.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using test::CliRun;
using test::expectOneLineFailure;
using test::runDropscope;

const std::string kOneSphere = std::string(DROPSCOPE_TEST_DATA_DIR) + "/scenes/one_sphere.json";

TEST(Cli, BadArgumentsExitTwoWithOneLine) {
    for (const auto& arguments : std::vector<std::vector<std::string>>{
             {"inspect"}, {"inspect", kOneSphere, "extra"}, {"inspect", "--jsn", kOneSphere}, {"--frobnicate"}}) {
        SCOPED_TRACE(arguments.back());
        const CliRun run = runDropscope(arguments);
        expectOneLineFailure(run);
        EXPECT_TRUE(run.err.starts_with("dropscope: ")) << run.err;
    }
}

TEST(Cli, UnknownCommandIsNamed) {
    const CliRun run = runDropscope({"render", kOneSphere});
    expectOneLineFailure(run);
    EXPECT_EQ(
        run.err,
        "dropscope: unknown command \"render\" (known: inspect, query, trace, snapshot, mie) (see dropscope --help)\n");
}

TEST(Cli, NoCommandPrintsHelpAndExitsTwo) {
    const CliRun run = runDropscope({});
    expectOneLineFailure(run);
    EXPECT_NE(run.out.find("inspect"), std::string::npos) << run.out;
}

TEST(Cli, HelpExitsZero) {
    const CliRun top = runDropscope({"--help"});
    EXPECT_EQ(top.status, kExitSuccess);
    EXPECT_NE(top.out.find("inspect"), std::string::npos);
    const CliRun inspect = runDropscope({"inspect", "--help"});
    EXPECT_EQ(inspect.status, kExitSuccess);
    EXPECT_NE(inspect.out.find("--json"), std::string::npos);
    EXPECT_EQ(inspect.err, "");
}

TEST(Cli, VersionPrintsTheProjectVersionAndExitsZero) {
    const CliRun run = runDropscope({"--version"});
    EXPECT_EQ(run.status, kExitSuccess);
    EXPECT_EQ(run.out, "dropscope " + std::string(dropscopeVersion()) + "\n");
    EXPECT_EQ(run.err, "");
    EXPECT_TRUE(std::regex_match(std::string(dropscopeVersion()), std::regex(R"([0-9]+\.[0-9]+\.[0-9]+)")))
        << dropscopeVersion();
    EXPECT_NE(runDropscope({"--help"}).out.find("--version"), std::string::npos);
}

}  // namespace
}  // namespace dropscope
