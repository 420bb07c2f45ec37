#include "tree/LargePageAllocator.hpp"
#include "tree/Octree.hpp"

#include "geometry/RandomGeometry.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace dropscope {
namespace {

// The VmFlags line of the mapping of /proc/self/smaps that holds `address` (empty when none does).
std::string mappingFlags(const void* address) {
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t low = 0;
        std::uintptr_t high = 0;
        char dash = 0;
        std::istringstream header(line);
        if (header >> std::hex >> low >> dash >> high && dash == '-') {
            inside = low <= at && at < high;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line;
        }
    }
    return {};
}

TEST(LargePageAllocator, LargeArraysAreMappedAlignedAndAdvisedForHugePages) {
    const std::size_t before = largePageBytesInUse();
    {
        std::vector<std::uint32_t, LargePageAllocator<std::uint32_t>> large(1'000'000);  // 4 MB
        std::iota(large.begin(), large.end(), 0u);
        EXPECT_EQ(large[999'999], 999'999u);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kLargePageBytes, 0u);
        if (largePagesAdvised()) {
            const std::size_t page = systemPageBytes();
            EXPECT_EQ(largePageBytesInUse() - before, (4'000'000u + page - 1) / page * page);  // whole pages
            // "hg": madvise(MADV_HUGEPAGE) took; the kernel backs the mapping with huge pages when THP allows. A
            // kernel built without THP refuses the advice and shows no such flag.
            if (std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled")) {
                const std::string flags = mappingFlags(large.data());
                ASSERT_FALSE(flags.empty()) << "no mapping holds the array";
                EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
            }
        } else {
            EXPECT_EQ(largePageBytesInUse(), before);  // operator new, which malloc's statistics count
        }
    }
    EXPECT_EQ(largePageBytesInUse(), before) << "the mapping is released with the array";
}

TEST(LargePageAllocator, SmallArraysComeFromOperatorNew) {
    const std::size_t before = largePageBytesInUse();
    std::vector<double, LargePageAllocator<double>> small(1000, 2.5);
    small.push_back(3.5);
    EXPECT_EQ(small.back(), 3.5);
    EXPECT_EQ(largePageBytesInUse(), before);
    // Grown past the threshold by push_back, copied into a mapping, and back under it by shrink_to_fit.
    for (int k = 0; k < 300'000; ++k) small.push_back(static_cast<double>(k));
    if (largePagesAdvised()) {
        EXPECT_GT(largePageBytesInUse(), before);
    }
    EXPECT_EQ(small[1001 + 299'999], 299'999.0);
    small.resize(10);
    small.shrink_to_fit();
    EXPECT_EQ(largePageBytesInUse(), before);
    EXPECT_EQ(small[0], 2.5);
}

// The octree's arrays that a ray's search reads take it: a cloud of 600,000 droplets has 19 MB of exact spheres,
// about 13 MB of sphere blocks and 3 MB of their ids, each above the threshold, against well under 1 MiB of
// cells and grid; it still finds what a brute-force search finds.
TEST(LargePageAllocator, TheOctreesLargestArraysAreMappedForHugePages) {
    if (!largePagesAdvised()) {
        GTEST_SKIP() << "this build takes them from operator new (not Linux, or AddressSanitizer)";
    }
    testing::Rng rng(7);
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.reserve(600'000);
    for (int i = 0; i < 600'000; ++i) {
        shapes.push_back(std::make_unique<Sphere>(testing::randomPoint(rng, 1.0), 0.0015));
    }
    const std::size_t before = largePageBytesInUse();
    const Octree tree(std::move(shapes));
    const std::size_t mapped = largePageBytesInUse() - before;
    // bytesUsed also counts the shapes' owning pointers, which the search does not read.
    const std::size_t searched = tree.bytesUsed() - tree.shapes().capacity() * sizeof(std::unique_ptr<Shape>);
    EXPECT_LE(mapped, searched + 4 * systemPageBytes());
    EXPECT_GE(mapped, searched - (std::size_t{1} << 20)) << "an array of the search is not mapped";
    for (int i = 0; i < 30; ++i) {
        const Point from = testing::randomPoint(rng, 1.5);
        const Direction d = testing::randomDirection(rng);
        const RayHit hit = tree.firstHit(from, d);
        const RayHit expected = bruteForceFirstHit(tree.shapes(), from, d);
        EXPECT_EQ(hit.shape, expected.shape) << "ray " << i;
        EXPECT_EQ(hit.distance, expected.distance) << "ray " << i;
    }
}

}  // namespace
}  // namespace dropscope
