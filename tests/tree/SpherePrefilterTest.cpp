#include "tree/SpherePrefilter.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace dropscope {
namespace {

using testing::Rng;

using Candidates = std::uint64_t (*)(const SphereBlock*, unsigned, const PrefilterRay&);

// A sphere and a ray near it.
struct Case {
    SphereGeometry sphere;
    Point origin;
    Direction direction;
};

Case randomCase(Rng& rng, int i) {
    const double radius = std::pow(10.0, testing::uniform(rng, -4.0, 1.0));
    const Point centre = testing::randomPoint(rng, std::pow(10.0, testing::uniform(rng, -1.0, 3.0)));
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
    return {sphere, p, d};
}

// Every sphere the exact test would let win (0 < t <= best) is a candidate, whatever the best so far,
// for both implementations; and spheres far off the ray are not.
void expectConservative(Candidates candidates) {
    Rng rng(17);
    int hits = 0;
    for (int i = 0; i < 200000; ++i) {
        const Case c = randomCase(rng, i);
        SphereBlock block;
        block.pack(0, c.sphere);
        for (unsigned lane = 1; lane < SphereBlock::kWidth; ++lane) block.clear(lane);
        const double t = c.sphere.distanceToSurface(c.origin, c.direction);
        const double scale = c.sphere.center.cwiseAbs().maxCoeff() + c.sphere.radius;
        const double slack = kPrefilterSlackRelative * (c.origin.cwiseAbs().maxCoeff() + scale);
        const double bests[] = {std::numeric_limits<double>::infinity(), t, std::nextafter(t, 0.0)};
        for (double best : bests) {
            const PrefilterRay ray{{c.origin.x(), c.origin.y(), c.origin.z()},
                                   {c.direction.x(), c.direction.y(), c.direction.z()},
                                   slack,
                                   best + slack};
            const std::uint64_t mask = candidates(&block, 1, ray) & 1;
            if (t > 0.0 && t <= best) {
                ++hits;
                ASSERT_EQ(mask, 1u) << "case " << i << ": t = " << t << ", best = " << best;
            }
        }
        // The same sphere moved 3 radii off the ray is never a candidate.
        block.pack(0, SphereGeometry::make(
                          c.sphere.center +
                              3.1 * c.sphere.radius * Direction(c.direction.vector().cross(Point(1, 2, 3))).vector(),
                          c.sphere.radius));
        const PrefilterRay ray{{c.origin.x(), c.origin.y(), c.origin.z()},
                               {c.direction.x(), c.direction.y(), c.direction.z()},
                               slack,
                               std::numeric_limits<double>::infinity()};
        if ((c.origin - c.sphere.center).norm() < 1.1 * c.sphere.radius) {
            EXPECT_EQ(candidates(&block, 1, ray) & 1, 0u) << "case " << i;
        }
    }
    EXPECT_GT(hits, 100000);
}

TEST(SpherePrefilter, Sse2NeverRejectsAWinningSphere) { expectConservative(sphereCandidatesSse2); }

TEST(SpherePrefilter, Avx2NeverRejectsAWinningSphere) {
    if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU";
    expectConservative(sphereCandidatesAvx2);
}

// Unused lanes and lanes beyond `count` are never candidates; a block run of 64 spheres maps lane k to bit k.
TEST(SpherePrefilter, LanesMapToBits) {
    SphereBlock blocks[16];
    for (unsigned k = 0; k < 64; ++k) {
        const double y = k % 3 == 0 ? 0.0 : 5.0;  // every third sphere lies on the x axis, the ray's line
        blocks[k / 4].pack(k % 4, SphereGeometry::make(Point(static_cast<double>(k), y, 0.0), 0.25));
    }
    blocks[15].clear(3);
    const PrefilterRay ray{{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1e-12, std::numeric_limits<double>::infinity()};
    std::uint64_t expected = 0;
    for (unsigned k = 0; k < 63; ++k) expected |= std::uint64_t{k % 3 == 0} << k;  // lane 63 is cleared
    EXPECT_EQ(sphereCandidates(blocks, 64, ray), expected);
    EXPECT_EQ(sphereCandidates(blocks, 10, ray), expected & 0x3ff);
}

}  // namespace
}  // namespace dropscope
