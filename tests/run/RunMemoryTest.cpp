// docs/limits.md, "Memory": what a trace will allocate, estimated before it starts, and the refusal.
#include "run/RunMemory.hpp"

#include "tally/DetectorTallies.hpp"
#include "tally/ScoreBytes.hpp"
#include "tally/StandardTallies.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

TEST(RunMemory, CountsATallyCopyPerThreadAndTheMergedOnePathsAndRecords) {
    const TallySet tallies = standardTallies(1000, PolarisationModel::Stokes, WavelengthBins{100, 400.0, 700.0});
    std::vector<std::byte> bytes;
    ScoreWriter out(bytes);
    tallies.writeScores(out);
    // The spectral table alone: 1000 x 100 cells of at least one 8-byte counter.
    ASSERT_GT(bytes.size(), 800'000u);

    TraceSettings settings;
    settings.photons = 1000;
    settings.paths = 5000;  // more than the photons: only 1000 are recorded
    settings.threads = 3;
    const TraceMemory need = estimateTraceMemory(tallies, settings, 20'000);
    EXPECT_EQ(need.tallyBytes, static_cast<double>(bytes.size()));
    EXPECT_EQ(need.threads, 3);
    EXPECT_EQ(need.pathBytes, 1000 * kPathBytesEstimate);
    EXPECT_EQ(need.recordBytes, 16'000.0 * sizeof(DetectorHit) * 4);  // at most 16 hits per photon, per copy
    EXPECT_EQ(need.total(), 5 * need.tallyBytes + need.pathBytes + need.recordBytes);
    // Rank 0 of an MPI run also holds one other rank's result while merging: two tally copies, its records
    // as bytes and as records, its paths as bytes.
    const TraceMemory merging = estimateTraceMemory(tallies, settings, 20'000, 3);
    EXPECT_EQ(merging.total(), 7 * need.tallyBytes + 2 * need.pathBytes + 1.5 * need.recordBytes);
}

TEST(RunMemory, RefusesOnlyWhatDoesNotFit) {
    TraceMemory need;
    need.tallyBytes = 2e9;
    need.threads = 2;
    need.pathBytes = 1e9;
    EXPECT_FALSE(traceMemoryProblem(need, 9e9).has_value());
    EXPECT_EQ(traceMemoryProblem(need, 8.5e9).value_or("none"),
              "this trace needs about 9 GB (tallies 2 GB per thread x 2 threads and two more copies, paths 1 GB, "
              "detector records 0 bytes), more than the 8.5 GB this machine has available (docs/limits.md)");
    need.mergesRanks = true;
    EXPECT_EQ(traceMemoryProblem(need, 8.5e9).value_or("none"),
              "this trace needs about 14 GB (tallies 2 GB per thread x 2 threads and four more copies to merge the "
              "ranks, paths 2 GB, detector records 0 bytes), more than the 8.5 GB this machine has available "
              "(docs/limits.md)");
    // --photons near 2^64: the records' cap of 16 per photon must not wrap around.
    TraceSettings huge;
    huge.photons = std::uint64_t{1} << 62;
    huge.threads = 1;
    EXPECT_EQ(estimateTraceMemory(TallySet{}, huge, 10'000'000).recordBytes, 1e7 * sizeof(DetectorHit) * 2);
}

}  // namespace
}  // namespace dropscope
