// A run split into consecutive photon ranges, each packed as an MPI rank sends it and merged as rank 0 does,
// against the same run in one piece: the merged result must be the same bits (tallies, paths, photons), so
// that `mpirun -np N dropscope trace` writes the files of one process for any N.
#include "run/RankResult.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/OrderTally.hpp"
#include "tally/StandardTallies.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace dropscope {
namespace {

std::string sceneText(const std::string& relative) {
    std::ifstream in(std::string(DROPSCOPE_SOURCE_DIR) + "/" + relative);
    EXPECT_TRUE(in) << relative;
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct SplitCase {
    const char* name;
    Scene scene;
    TallySet tallies;
    TraceSettings settings;
    bool haloes;
};

// The detectors scene with records on the screen and the absorption detector, polarised, with ray orders and
// diffraction (every tally type, hit records and Diffract events).
SplitCase detectorsCase() {
    std::string text = sceneText("tests/data/scenes/detectors.json");
    const auto addRecord = [&](const std::string& end, const std::string& withRecord) {
        const std::size_t at = text.find(end);
        EXPECT_NE(at, std::string::npos) << end;
        text.replace(at, end.size(), withRecord);
    };
    addRecord("\"pixels\": [48, 48]}", "\"pixels\": [48, 48], \"record\": 300}");
    addRecord("{\"type\": \"shape_absorption\", \"name\": \"absorbed\"}",
              "{\"type\": \"shape_absorption\", \"name\": \"absorbed\", \"record\": 5}");
    SplitCase split{"detectors", parseScene(text, "detectors.json"), {}, {}, true};
    split.settings.transport.polarisation = PolarisationModel::Stokes;
    split.settings.transport.diffraction = DiffractionModel::Fraunhofer;
    split.tallies = standardTallies(90, PolarisationModel::Stokes);
    split.tallies.add(std::make_unique<OrderTally>(90, true));
    addDetectorTallies(split.tallies, split.scene, PolarisationModel::Stokes);
    return split;
}

// A sunlit drop: wavelengths in four bands, unpolarised.
SplitCase spectralCase() {
    SplitCase split{
        "sunlit", loadScene(std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/sunlit-rainbow.json"), {}, {}, false};
    split.settings.transport.polarisation = PolarisationModel::None;
    const auto [lo, hi] = wavelengthRangeNm(split.scene.sources, split.scene.wavelengthNm);
    split.tallies = standardTallies(60, PolarisationModel::None, WavelengthBins{4, lo, hi});
    return split;
}

class RankResultSplit : public ::testing::TestWithParam<int> {};

TEST_P(RankResultSplit, MergedRangesAreTheBitsOfOneRun) {
    SplitCase split = GetParam() == 0 ? detectorsCase() : spectralCase();
    const OpticalScene optical(split.scene, split.haloes);
    constexpr std::uint64_t kPhotons = 6000;
    split.settings.photons = kPhotons;
    split.settings.seed = 77;
    split.settings.paths = 40;
    split.settings.threads = 1;
    const TraceResult whole = runTrace(optical, split.scene.sources, split.settings, split.tallies);

    // Three "ranks" of unequal shares; the paths' photons [0, 40) fall in the first two.
    const std::uint64_t bounds[] = {0, 25, 3100, kPhotons};
    std::vector<TraceResult> parts;
    for (int rank = 0; rank < 3; ++rank) {
        TraceSettings own = split.settings;
        own.firstPhoton = bounds[rank];
        own.photons = bounds[rank + 1] - bounds[rank];
        parts.push_back(runTrace(optical, split.scene.sources, own, split.tallies));
    }
    TraceResult merged = std::move(parts[0]);
    // In the order rank 0 receives them, and in the opposite order: exact merges do not care.
    for (int rank : {2, 1}) mergeRankResult(merged, packRankResult(parts[static_cast<std::size_t>(rank)]));

    SCOPED_TRACE(split.name);
    EXPECT_EQ(merged.photons, kPhotons);
    ASSERT_EQ(merged.paths.size(), 40u);
    EXPECT_EQ(merged.paths[30].photon, 30u);
    EXPECT_GE(whole.tallies.size(), 3u);  // fates, angular, spectral at least
    // Every score and every recorded event, bit for bit.
    EXPECT_TRUE(packRankResult(merged) == packRankResult(whole));
    ResultReport wholeReport, mergedReport;
    whole.tallies.report(wholeReport);
    merged.tallies.report(mergedReport);
    EXPECT_EQ(wholeReport.tables(), mergedReport.tables());
}

INSTANTIATE_TEST_SUITE_P(RankResult, RankResultSplit, ::testing::Values(0, 1));

TEST(RankResult, BytesOfAnotherRunAreRefused) {
    const Scene scene = loadScene(std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json");
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 100;
    settings.threads = 1;
    const TraceResult coarse = runTrace(optical, scene.sources, settings, standardTallies(30, PolarisationModel::None));
    TraceResult fine = runTrace(optical, scene.sources, settings, standardTallies(60, PolarisationModel::None));
    EXPECT_THROW(mergeRankResult(fine, packRankResult(coarse)), std::runtime_error);
    std::vector<std::byte> bytes = packRankResult(fine);
    bytes.pop_back();
    EXPECT_THROW(mergeRankResult(fine, bytes), std::runtime_error);
    bytes = packRankResult(fine);
    bytes.push_back(std::byte{0});
    EXPECT_THROW(mergeRankResult(fine, bytes), std::runtime_error);
}

}  // namespace
}  // namespace dropscope
