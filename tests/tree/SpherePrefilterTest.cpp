#include "tree/SpherePrefilter.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace dropscope {
namespace {

using testing::Rng;

using Candidates = std::uint64_t (*)(const float*, unsigned, unsigned, const PrefilterRay&);

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A sphere, a ray near it, and the octree's side of the prefilter: the frame the sphere is packed in and the
// ray's shift along itself (as the octree shifts it to where it enters the root).
struct Case {
    SphereGeometry sphere;
    Point origin;
    Direction direction;
    PrefilterFrame frame;
    double shift;
};

Case randomCase(Rng& rng, int i) {
    // Every length times a unit from 1e-40 to 1e40 in one case of four (single precision's subnormals and overflow
    // lie beyond 1e-38 and 3e38, which only the frame's scaling keeps the prefilter from).
    const double unit = i % 16 < 12 ? 1.0 : std::pow(10.0, testing::uniform(rng, -40.0, 40.0));
    const double radius = std::pow(10.0, testing::uniform(rng, -4.0, 1.0)) * unit;
    const Point centre = testing::randomPoint(rng, std::pow(10.0, testing::uniform(rng, -1.0, 3.0)) * unit);
    const SphereGeometry sphere = SphereGeometry::make(centre, radius);
    Direction d = testing::randomDirection(rng);
    const Direction side(d.vector().cross(testing::randomDirection(rng).vector()));
    Point p;
    switch (i % 4) {
    case 0:  // grazing: the line passes within 1e-8 R of the surface, on either side
        p = centre + radius * (1.0 + testing::uniform(rng, -1e-8, 1e-8)) * side.vector() -
            testing::uniform(rng, -3.0, 100.0) * radius * d.vector();
        break;
    case 1:  // inside
        p = centre + testing::uniform(rng, 0.0, 0.999) * radius * side.vector();
        break;
    case 2:  // on the surface within its band, leaving, entering or tangent
        p = centre + radius * (1.0 + testing::uniform(rng, -2e-9, 2e-9)) * side.vector();
        if (rng() % 2 == 0) d = testing::randomDirection(rng);
        break;
    default:  // anywhere around it
        p = centre + testing::randomPoint(rng, 20.0 * radius);
        break;
    }
    // The anchor from on the sphere's centre to a thousand radii away, the frame's half-side from the sphere's
    // reach to 1e3 times more; every other ray starts far behind its origin and is shifted forward to it (the
    // ray is the same line, its distances counted from the far point).
    const Point anchor = centre + testing::randomPoint(rng, radius * std::pow(10.0, testing::uniform(rng, -3.0, 3.0)));
    const double halfSide = ((centre - anchor).cwiseAbs().maxCoeff() + radius) * testing::uniform(rng, 1.0, 1e3);
    const double back = i % 8 < 4 ? 0.0 : std::pow(10.0, testing::uniform(rng, -2.0, 4.0)) * radius;
    return {sphere, p - back * d.vector(), d, PrefilterFrame::around(anchor, halfSide), back};
}

PrefilterRay rayFor(const Case& c) {
    const double scale = c.origin.cwiseAbs().maxCoeff() + c.sphere.center.cwiseAbs().maxCoeff() + c.sphere.radius;
    return PrefilterRay::make(c.origin, c.direction, c.shift, c.frame, c.frame.reach(c.sphere),
                              kPrefilterSlackRelative * scale);
}

// A cell's packed spheres as the octree holds them: `count` lanes (padded to 4, the padding cleared, and every lane
// cleared until packed) in blocks of their own, then `blocksAfter` blocks of NaN, which the read-ahead may read
// as it reads the octree's next cells. Without them any read beyond the cell is one past its allocation, which
// AddressSanitizer reports.
class PackedCell {
public:
    explicit PackedCell(unsigned count, unsigned blocksAfter = 0)
        : blocks_(SphereLanes::blocksFor(count) + blocksAfter), lanes_(blocks_.data(), count) {
        for (SphereBlock& block : blocks_) {
            for (float& value : block.values) value = std::numeric_limits<float>::quiet_NaN();
        }
        for (unsigned lane = 0; lane < lanes_.stride(); ++lane) lanes_.clear(lane);
    }
    PackedCell(const SphereGeometry& sphere, const PrefilterFrame& frame) : PackedCell(1) {
        lanes_.pack(0, sphere, frame);
    }
    PackedCell(const PackedCell&) = delete;
    PackedCell& operator=(const PackedCell&) = delete;

    SphereLanes& lanes() { return lanes_; }
    // The first `count` lanes' candidates by `candidates`.
    std::uint64_t test(Candidates candidates, unsigned count, const PrefilterRay& ray) const {
        return candidates(lanes_.x(), lanes_.stride(), count, ray);
    }

private:
    std::vector<SphereBlock> blocks_;
    SphereLanes lanes_;
};

// Every sphere the exact test would let win (0 < t <= best) is a candidate, whatever the best so far,
// for both implementations; and spheres far off the ray are not.
void expectConservative(Candidates candidates) {
    Rng rng(17);
    int hits = 0;
    int rejected = 0;
    for (int i = 0; i < 200000; ++i) {
        const Case c = randomCase(rng, i);
        const PackedCell cell(c.sphere, c.frame);
        const double t = c.sphere.distanceToSurface(c.origin, c.direction);
        PrefilterRay ray = rayFor(c);
        for (double best : {kInfinity, t, std::nextafter(t, 0.0)}) {
            ray.setBest(best);
            const std::uint64_t mask = cell.test(candidates, 1, ray) & 1;
            if (t > 0.0 && t <= best) {
                ++hits;
                ASSERT_EQ(mask, 1u) << "case " << i << ": t = " << t << ", best = " << best;
            }
        }
        // The same sphere moved 3 radii off the ray is never a candidate, once the slack is below a radius.
        const SphereGeometry off = SphereGeometry::make(
            c.sphere.center + 3.1 * c.sphere.radius * Direction(c.direction.vector().cross(Point(1, 2, 3))).vector(),
            c.sphere.radius);
        const PackedCell offCell(off, c.frame);
        ray.setBest(kInfinity);
        if ((c.origin + c.shift * c.direction.vector() - c.sphere.center).norm() < 1.1 * c.sphere.radius &&
            ray.slack < c.sphere.radius * c.frame.scale) {
            ++rejected;
            EXPECT_EQ(offCell.test(candidates, 1, ray) & 1, 0u) << "case " << i;
        }
    }
    EXPECT_GT(hits, 100000);
    EXPECT_GT(rejected, 10000);
}

TEST(SpherePrefilter, Sse2NeverRejectsAWinningSphere) { expectConservative(sphereCandidatesSse2); }

TEST(SpherePrefilter, Avx2NeverRejectsAWinningSphere) {
    if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU";
    expectConservative(sphereCandidatesAvx2);
}

TEST(SpherePrefilter, Avx512NeverRejectsAWinningSphere) {
    if (!cpuHasAvx512()) GTEST_SKIP() << "no AVX-512 on this CPU";
    expectConservative(sphereCandidatesAvx512);
}

// The least float radius that AVX2 accepts for the sphere in `lane` of `cell`'s first `count` (every
// comparison's side grows with the radius, so acceptance is monotone in it; a bisection over the floats' bit
// patterns, which order positive floats); 0 when it accepts a radius of 0. The cell is left as it was.
float leastAcceptedRadius(PackedCell& cell, unsigned count, unsigned lane, const PrefilterRay& ray) {
    const float radius = cell.lanes().radius(lane);
    const auto accepts = [&](std::uint32_t bits) {
        cell.lanes().radius(lane) = std::bit_cast<float>(bits);
        return (cell.test(sphereCandidatesAvx2, count, ray) >> lane & 1) != 0;
    };
    std::uint32_t rejected = 0;
    std::uint32_t accepted = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::max());
    float least = 0.0f;
    if (!accepts(rejected)) {
        while (accepted - rejected > 1) {
            const std::uint32_t middle = rejected + (accepted - rejected) / 2;
            (accepts(middle) ? accepted : rejected) = middle;
        }
        least = std::bit_cast<float>(accepted);
    }
    cell.lanes().radius(lane) = radius;
    return least;
}

// The AVX-512 version runs the AVX2 version's operations in the same order on twice as many lanes, so for any
// count the two give the same bits, down to spheres whose last rounding decides: half the lanes hold a radius
// at AVX2's boundary for their centre (the least it accepts, or the float below it), where a different
// rounding or a comparison made strict would flip a bit.
TEST(SpherePrefilter, Avx512GivesTheAvx2Bits) {
    if (!cpuHasAvx512() || !cpuHasAvx2()) GTEST_SKIP() << "no AVX-512 or AVX2 on this CPU";
    Rng rng(29);
    int candidates = 0;
    int boundaries = 0;
    for (int i = 0; i < 4000; ++i) {
        const Case c = randomCase(rng, i);
        PrefilterRay ray = rayFor(c);
        ray.setBest(i % 2 == 0 ? kInfinity : c.sphere.distanceToSurface(c.origin, c.direction));
        // 24 spheres around the case's: about its size, within a few radii of it, some on the ray's line.
        PackedCell cell(24);
        for (unsigned k = 0; k < 24; ++k) {
            const double radius = c.sphere.radius * testing::uniform(rng, 0.5, 2.0);
            const Point centre = c.sphere.center + testing::randomPoint(rng, (k % 3 == 0 ? 0.1 : 4.0) * radius);
            cell.lanes().pack(k, SphereGeometry::make(centre, radius), c.frame);
            if (k % 2 == 1) {
                const float least = leastAcceptedRadius(cell, 24, k, ray);
                if (least > 0.0f) {
                    cell.lanes().radius(k) = k % 4 == 1 ? least : std::nextafter(least, 0.0f);
                    ++boundaries;
                }
            }
        }
        for (unsigned count = 1; count <= 24; ++count) {
            const std::uint64_t within = (std::uint64_t{1} << count) - 1;
            const std::uint64_t avx2 = cell.test(sphereCandidatesAvx2, count, ray) & within;
            ASSERT_EQ(cell.test(sphereCandidatesAvx512, count, ray) & within, avx2)
                << "case " << i << ", count " << count;
            if (count == 24) candidates += std::popcount(avx2);
        }
    }
    EXPECT_GT(boundaries, 4000 * 12 / 2);
    EXPECT_GT(candidates, 4000 * 24 / 10);  // neither all rejected nor all accepted
    EXPECT_LT(candidates, 4000 * 24 * 9 / 10);
}

// Unused lanes and lanes beyond `count` are never candidates, and lane k maps to bit k, for every count from 1 to
// 64 and every implementation: in a cell of exactly that many spheres (the AVX2 version's last step of four, the
// AVX-512 one's masked last step, neither reading past the cell), among the first of a cell of 64 (a later group
// of a larger cell), and with the read-ahead over kPrefilterFixedLanes lanes (with no more than the 8 blocks
// from the cell's first that the octree allows it), whose candidates beyond count are dropped. Each of the four
// arrays decides some bits: a sphere is a candidate when it is ahead of the ray (x) and on its line (y and z 0)
// or large enough to reach it from off it (the radius); each choice follows its own non-periodic pattern, so
// no two lanes of any array can be swapped unseen.
TEST(SpherePrefilter, LanesMapToBits) {
    const PrefilterFrame frame = PrefilterFrame::around(Point(-10.0, 1.0, -2.0), 80.0);
    constexpr std::uint64_t kOnTheLine = 0x9e3779b97f4a7c15;
    constexpr std::uint64_t kOffAlongY = 0xbf58476d1ce4e5b9;  // else along z
    constexpr std::uint64_t kLarge = 0x94d049bb133111eb;
    constexpr std::uint64_t kAhead = 0xd6e8feb86659fd93;
    const auto bit = [](std::uint64_t pattern, unsigned k) { return ((pattern >> k) & 1) != 0; };
    const auto sphere = [&](unsigned k) {
        const double off = bit(kOnTheLine, k) ? 0.0 : 5.0;
        const double x = bit(kAhead, k) ? static_cast<double>(k) : -10.0 - static_cast<double>(k);
        const Point centre(x, bit(kOffAlongY, k) ? off : 0.0, bit(kOffAlongY, k) ? 0.0 : off);
        return SphereGeometry::make(centre, bit(kLarge, k) ? 6.0 : 0.25);  // 6 reaches the line from 5 off it
    };
    const PrefilterRay ray =
        PrefilterRay::make(Point(-1.0, 0.0, 0.0), Direction(1.0, 0.0, 0.0), 0.0, frame, 90.0, 1e-12);
    PackedCell all(64);
    for (unsigned k = 0; k < 63; ++k) all.lanes().pack(k, sphere(k), frame);  // lane 63 stays cleared
    const std::uint64_t expected = kAhead & (kOnTheLine | kLarge) & ~(std::uint64_t{1} << 63);
    for (unsigned count = 1; count <= 64; ++count) {
        const std::uint64_t within = count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
        PackedCell exact(count);
        PackedCell readAhead(count, 8 - std::min(8u, SphereLanes::blocksFor(count)));
        for (unsigned k = 0; k < std::min(count, 63u); ++k) {
            exact.lanes().pack(k, sphere(k), frame);
            readAhead.lanes().pack(k, sphere(k), frame);
        }
        std::vector<Candidates> implementations = {sphereCandidatesSse2};
        if (cpuHasAvx2()) implementations.push_back(sphereCandidatesAvx2);
        if (cpuHasAvx512()) implementations.push_back(sphereCandidatesAvx512);
        for (const Candidates candidates : implementations) {
            EXPECT_EQ(exact.test(candidates, count, ray) & within, expected & within) << count;
            EXPECT_EQ(all.test(candidates, count, ray) & within, expected & within) << count;
        }
        EXPECT_EQ(sphereCandidates(exact.lanes(), count, ray), expected & within) << count;
        EXPECT_EQ(sphereCandidates(readAhead.lanes().x(), readAhead.lanes().stride(), count, true, ray),
                  expected & within)
            << count;
        EXPECT_EQ(sphereCandidates(all.lanes().x(), all.lanes().stride(), count, true, ray), expected & within)
            << count;
    }
}

// The bounds along the ray count from the ray's origin, not from the point it was shifted to: a sphere behind the
// origin and one wholly beyond the best so far are not candidates.
TEST(SpherePrefilter, DistancesCountFromTheOriginOfAShiftedRay) {
    const PrefilterFrame frame = PrefilterFrame::around(Point::Zero(), 21.0);
    PackedCell cell(4);
    const double centres[] = {-150.0, -90.0, 5.0, 20.0};  // ray distances of their centres: -50, 10, 105, 120
    for (unsigned lane = 0; lane < 4; ++lane) {
        cell.lanes().pack(lane, SphereGeometry::make(Point(centres[lane], 0.0, 0.0), 1.0), frame);
    }
    PrefilterRay ray =
        PrefilterRay::make(Point(-100.0, 0.0, 0.0), Direction(1.0, 0.0, 0.0), 100.0, frame, 151.0, 1e-10);
    EXPECT_EQ(sphereCandidates(cell.lanes(), 4, ray), 0b1110u);
    ray.setBest(110.0);
    EXPECT_EQ(sphereCandidates(cell.lanes(), 4, ray), 0b0110u);
    ray.setBest(20.0);
    EXPECT_EQ(sphereCandidates(cell.lanes(), 4, ray), 0b0010u);
}

// The frame scales the root's half-side into [1, 2) by a power of two. A ray whose X (in the frame's units)
// leaves [kPrefilterSmallestExtent, kPrefilterLargestExtent] lets every packed sphere through, and a sphere
// reaching beyond the largest is not packed.
TEST(SpherePrefilter, OutsideItsRangeEverySphereIsACandidate) {
    const PrefilterFrame frame = PrefilterFrame::around(Point::Zero(), 3.0);
    EXPECT_EQ(frame.scale, 0.5);
    EXPECT_EQ(PrefilterFrame::around(Point::Zero(), 1e-30).scale * 1e-30, std::ldexp(1e-30, -std::ilogb(1e-30)));
    EXPECT_EQ(PrefilterFrame::around(Point::Zero(), 0.0).scale, 1.0);
    PackedCell cell(4);
    cell.lanes().pack(0, SphereGeometry::make(Point(1.0, 0.0, 0.0), 0.5), frame);
    cell.lanes().pack(1, SphereGeometry::make(Point(-1.0, 2.0, 0.0), 0.5), frame);
    const Direction up(0.0, 1.0, 0.0);
    EXPECT_EQ(sphereCandidates(cell.lanes(), 4, PrefilterRay::make(Point(0.0, 4e15, 0.0), up, 0.0, frame, 3.0, 1.0)),
              0b11u);
    EXPECT_EQ(sphereCandidates(cell.lanes(), 4, PrefilterRay::make(Point(0.0, 5.0, 0.0), up, 0.0, frame, 3.0, 1e-12)),
              0u);
    // A ray at the anchor with spheres reaching 1e-13 of the half-side: X is below 2^-40.
    PackedCell tiny(SphereGeometry::make(Point(1e-14, 0.0, 0.0), 1e-14), frame);
    EXPECT_EQ(sphereCandidates(tiny.lanes(), 4, PrefilterRay::make(Point::Zero(), up, 0.0, frame, 2e-14, 1e-30)), 0b1u);
    EXPECT_TRUE(SphereLanes::packable(SphereGeometry::make(Point(-1e6, 3e6, 0.0), 0.5), frame));
    EXPECT_FALSE(SphereLanes::packable(SphereGeometry::make(Point(0.0, 3e15, 0.0), 0.5), frame));
    EXPECT_FALSE(SphereLanes::packable(SphereGeometry::make(Point(0.0, 0.0, 0.0), 3e15), frame));
    // A band SphereGeometry::make would not recompute: the candidates' exact test could not reproduce it.
    SphereGeometry widened = SphereGeometry::make(Point(1.0, 0.0, 0.0), 0.5);
    widened.band *= 2.0;
    EXPECT_FALSE(SphereLanes::packable(widened, frame));
}

}  // namespace
}  // namespace dropscope
