// The droplet cloud's hash grid against brute force: every item whose bounds meet a query's bounds
// inside the domain is visited, for items of every size, partly outside the domain, in crowded cells.
#include "scene/RandomStream.hpp"
#include "scene/SpatialHashGrid.hpp"

#include <gtest/gtest.h>

#include <set>

namespace dropscope {
namespace {

using Bounds = SpatialHashGrid::Bounds;

double uniform(RandomStream& random, double a, double b) { return a + random.uniform() * (b - a); }

// A box of half-widths up to `halfWidth` centred anywhere in `centers`.
Bounds randomBox(RandomStream& random, const Bounds& centers, double halfWidth) {
    const Point center(uniform(random, centers.min().x(), centers.max().x()),
                       uniform(random, centers.min().y(), centers.max().y()),
                       uniform(random, centers.min().z(), centers.max().z()));
    const Eigen::Vector3d half(uniform(random, 0.0, halfWidth), uniform(random, 0.0, halfWidth),
                               uniform(random, 0.0, halfWidth));
    return {center - half, center + half};
}

std::set<std::uint32_t> visited(const SpatialHashGrid& grid, const Bounds& query) {
    std::set<std::uint32_t> items;
    grid.any(query, [&](std::uint32_t item, const SpatialHashGrid::Ball&) {
        items.insert(item);
        return false;
    });
    return items;
}

TEST(SpatialHashGrid, VisitsEveryItemWhoseBoundsMeetTheQuery) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        RandomStream random(seed, 0);
        const Bounds domain(Point(-1, 0, 2), Point(3, 2, 5));
        const double cellSize = uniform(random, 0.05, 0.5);
        SpatialHashGrid grid(domain, cellSize);
        std::vector<Bounds> items;
        for (std::uint32_t item = 0; item < 400; ++item) {
            // Mostly small items, some spanning many cells, some reaching outside the domain.
            const double halfWidth = item % 10 == 0 ? 1.0 : 0.1;
            const Bounds centers(domain.min().array() - 0.5, domain.max().array() + 0.5);
            items.push_back(randomBox(random, centers, halfWidth));
            grid.insert(item, items.back(), {items.back().center(), 0.0});
        }
        for (int q = 0; q < 300; ++q) {
            const Bounds query = randomBox(random, domain, 0.3).intersection(domain);
            const std::set<std::uint32_t> found = visited(grid, query);
            for (std::uint32_t item = 0; item < items.size(); ++item) {
                if (!items[item].intersects(query)) continue;
                ASSERT_TRUE(found.count(item)) << "seed " << seed << ", query " << q << ", item " << item;
            }
        }
    }
}

TEST(SpatialHashGrid, SmallItemsTakeOneEntryAndLargeOnesOnePerCellTheyCover) {
    const Bounds domain(Point(0, 0, 0), Point(10, 10, 10));
    SpatialHashGrid grid(domain, 1.0);
    EXPECT_EQ(grid.reach(), 0.5);
    const Bounds small(Point(2.2, 2.2, 2.2), Point(3.1, 3.1, 3.1));  // no wider than a cell
    EXPECT_EQ(grid.entriesFor(small), 1u);
    // 4 wide: shrunk by 0.5 on each side to [1.25, 4.25] on every axis, 4 cells per axis.
    const Bounds large(Point(0.75, 0.75, 0.75), Point(4.75, 4.75, 4.75));
    EXPECT_EQ(grid.entriesFor(large), 64u);
    EXPECT_EQ(grid.entriesFor(Bounds(Point(20, 20, 20), Point(21, 21, 21))), 0u);  // outside the domain
    grid.insert(0, small, {small.center(), 0.0});
    grid.insert(1, large, {large.center(), 0.0});
    EXPECT_EQ(grid.entryCount(), 65u);
    EXPECT_EQ(grid.occupiedCells(), 64u);  // the small item's cell is among the large one's
}

TEST(SpatialHashGrid, StopsAtTheFirstItemTheVisitorAccepts) {
    SpatialHashGrid grid(Bounds(Point(0, 0, 0), Point(1, 1, 1)), 0.1);
    for (std::uint32_t item = 0; item < 10; ++item) {
        const Point center = Point::Constant(0.5);
        grid.insert(item, Bounds(center, center), {center, 0.01 * item});
    }
    int visits = 0;
    const bool found = grid.any(Bounds(Point::Constant(0.45), Point::Constant(0.55)),
                                [&](std::uint32_t, const SpatialHashGrid::Ball& ball) {
                                    ++visits;
                                    return ball.radius == 0.05;
                                });
    EXPECT_TRUE(found);
    EXPECT_EQ(visits, 5);  // the newest entry of a cell comes first: 0.09, 0.08, ..., 0.05
}

TEST(SpatialHashGrid, HugeDomainsCoarsenTheCellsToFitTheKeys) {
    SpatialHashGrid grid(Bounds(Point(0, 0, 0), Point(1e9, 1, 1)), 1e-3);
    EXPECT_GE(grid.cellSize(), 1e9 / SpatialHashGrid::kMaxCellsPerAxis);
}

}  // namespace
}  // namespace dropscope
