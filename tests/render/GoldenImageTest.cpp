// Golden images: each case of tests/golden/cases.txt runs the real `dropscope snapshot` (in-process) and
// is compared with tests/golden/NAME.png within kGoldenChannelTolerance and kGoldenMaxDifferingShare. A
// failure leaves NAME-actual.png and NAME-diff.png in the build tree's golden-failures/ and names them.
#include "app/CliRun.hpp"
#include "render/GoldenCases.hpp"
#include "render/ImageComparison.hpp"
#include "render/RenderTolerances.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>

namespace dropscope {
namespace {

namespace fs = std::filesystem;
using test::GoldenCase;

const fs::path kGoldenDir = fs::path(DROPSCOPE_SOURCE_DIR) / "tests" / "golden";
const fs::path kCasesFile = kGoldenDir / "cases.txt";
const fs::path kSceneDir = fs::path(DROPSCOPE_TEST_DATA_DIR) / "scenes" / "golden";
const fs::path kFailureDir = DROPSCOPE_GOLDEN_FAILURE_DIR;

// At test registration a bad list registers no case; GoldenCases.ListIsWellFormed then says why.
std::vector<GoldenCase> casesOrNone() {
    try {
        return test::readGoldenCases(kCasesFile);
    } catch (const std::exception&) {
        return {};
    }
}

void writePng(const fs::path& file, const snapshot::Image& image) {
    std::ofstream(file, std::ios::binary) << snapshot::encodePng(image);
}

TEST(GoldenCases, ListIsWellFormed) {
    const std::vector<GoldenCase> cases = test::readGoldenCases(kCasesFile);
    EXPECT_GE(cases.size(), 5u);
    for (const GoldenCase& golden : cases) EXPECT_TRUE(fs::is_regular_file(kSceneDir / golden.scene)) << golden.scene;
}

TEST(GoldenCases, EveryGoldenImageBelongsToACase) {
    std::set<std::string> names;
    for (const GoldenCase& golden : test::readGoldenCases(kCasesFile)) names.insert(golden.name);
    for (const fs::directory_entry& entry : fs::directory_iterator(kGoldenDir)) {
        if (entry.path().extension() != ".png") continue;
        EXPECT_TRUE(names.contains(entry.path().stem().string()))
            << entry.path() << " is in no case of cases.txt (scripts/update-goldens.sh removes such files)";
    }
}

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, SnapshotMatchesTheGolden) {
    const GoldenCase& golden = GetParam();
    const fs::path actualFile = kFailureDir / (golden.name + "-actual.png");
    const fs::path diffFile = kFailureDir / (golden.name + "-diff.png");
    fs::create_directories(kFailureDir);
    fs::remove(diffFile);  // left by an earlier failure

    std::vector<std::string> arguments{"snapshot", (kSceneDir / golden.scene).string(), "--out", actualFile.string()};
    arguments.insert(arguments.end(), golden.arguments.begin(), golden.arguments.end());
    const test::CliRun run = test::runDropscope(arguments);
    ASSERT_EQ(run.status, kExitSuccess) << run.err;
    const snapshot::Image actual = snapshot::readPng(actualFile);

    const fs::path goldenFile = kGoldenDir / (golden.name + ".png");
    ASSERT_TRUE(fs::is_regular_file(goldenFile)) << goldenFile << " is missing; the snapshot is in " << actualFile
                                                 << " (scripts/update-goldens.sh makes the goldens)";
    const snapshot::Image expected = snapshot::readPng(goldenFile);
    const test::ImageDifference difference = test::compareImages(expected, actual, test::kGoldenChannelTolerance);
    if (difference.within(test::kGoldenMaxDifferingShare)) {
        fs::remove(actualFile);
        return;
    }
    if (!difference.sameSize) {
        FAIL() << golden.name << ": the snapshot is " << actual.width << "x" << actual.height << ", the golden "
               << expected.width << "x" << expected.height << "; actual: " << actualFile;
    }
    writePng(diffFile, test::differenceImage(expected, actual, test::kGoldenChannelTolerance));
    ADD_FAILURE() << golden.name << ": " << difference.differingPixels << " of " << difference.pixels
                  << " pixels differ by more than " << test::kGoldenChannelTolerance << " of 255 (largest difference "
                  << difference.largestChannelDifference << "); at most " << std::setprecision(3)
                  << 100.0 * test::kGoldenMaxDifferingShare << " % may differ\n  golden: " << goldenFile
                  << "\n  actual: " << actualFile << "\n  diff:   " << diffFile << " (differing pixels red)";
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenImage, ::testing::ValuesIn(casesOrNone()),
                         [](const ::testing::TestParamInfo<GoldenCase>& param) { return param.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenImage);

}  // namespace
}  // namespace dropscope
