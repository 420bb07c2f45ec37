#include "tree/BoundingBox.hpp"
#include "tree/Octree.hpp"

#include "geometry/Box.hpp"
#include "geometry/RandomGeometry.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace dropscope {
namespace {

using testing::Rng;

std::vector<std::unique_ptr<Shape>> randomScene(Rng& rng, int count, double halfWidth) {
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int i = 0; i < count; ++i) {
        const double size = testing::uniform(rng, 0.02, 0.6);
        shapes.push_back(testing::randomShape(rng, i, testing::randomPoint(rng, halfWidth), size));
    }
    return shapes;
}

// `count` spheres, each drawn as its radius, uniform in [minRadius, maxRadius), then its centre, uniform in the
// cube of half-side `halfWidth` about `centre` (one draw per statement: RandomGeometry.hpp).
std::vector<std::unique_ptr<Shape>> randomSpheres(Rng& rng, int count, double halfWidth, double minRadius,
                                                  double maxRadius, const Point& centre = Point::Zero()) {
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int i = 0; i < count; ++i) {
        const double radius = testing::uniform(rng, minRadius, maxRadius);
        shapes.push_back(std::make_unique<Sphere>(testing::randomPoint(rng, halfWidth, centre), radius));
    }
    return shapes;
}

std::vector<std::unique_ptr<Shape>> copies(const std::vector<std::unique_ptr<Shape>>& shapes) {
    std::vector<std::unique_ptr<Shape>> copied;
    for (const auto& shape : shapes) copied.push_back(shape ? shape->clone() : nullptr);
    return copied;
}

// The top grid's cells as the walk places them: the root's cube from its centre and half-side, 2^level cells a side.
struct GridGeometry {
    Point low;    // the lowest corner
    double cell;  // a cell's side
    int side;     // cells a side
};

GridGeometry gridGeometry(const CellBounds& root, int level) {
    const double half = 0.5 * root.sizes().maxCoeff();
    return {root.center().array() - half, std::ldexp(2.0 * half, -level), 1 << level};
}

// Bitwise agreement: same shape and the very same double.
void expectSameHit(const RayHit& actual, const RayHit& expected) {
    EXPECT_EQ(actual.shape, expected.shape);
    if (expected) {
        EXPECT_EQ(actual.distance, expected.distance);
    }
}

struct Ray {
    Point origin;
    Direction direction;
};

// Rays of every awkward kind: from outside, from inside shapes, from surface points, from cell
// mid-planes, edges and corners, and parallel to the axes.
std::vector<Ray> awkwardRays(Rng& rng, const Octree& tree, int count) {
    std::vector<Ray> rays;
    const CellBounds root = tree.rootBounds();
    const double half = 0.5 * root.sizes().maxCoeff();
    for (int i = 0; i < count; ++i) {
        Direction d = testing::randomDirection(rng);
        Point o = testing::randomPoint(rng, 1.2 * half, root.center());
        switch (i % 6) {
        case 0: break;
        case 1: {  // inside a shape
            const Shape* s = tree.shape(static_cast<ShapeId>(rng() % tree.slotCount()));
            if (s) o = testing::boundsCenter(*s);  // removed slots are empty
            break;
        }
        case 2: {  // on a surface: a brute-force hit point
            const RayHit hit = bruteForceFirstHit(tree.shapes(), o, d);
            if (hit) o = o + hit.distance * d.vector();
            d = testing::randomDirection(rng);
            break;
        }
        case 3: {  // on cell mid-planes, edges, corners at a random level
            const double cell = 2.0 * half / std::pow(2.0, static_cast<double>(rng() % 4));
            for (int axis = 0; axis < 1 + static_cast<int>(rng() % 3); ++axis) {
                o[axis] = root.min()[axis] + cell * std::round((o[axis] - root.min()[axis]) / cell);
            }
            break;
        }
        case 4: {  // axis-parallel: one or two zero components
            Eigen::Vector3d v = d.vector();
            v[static_cast<int>(rng() % 3)] = 0.0;
            if (rng() % 2) v[static_cast<int>(rng() % 3)] = 0.0;
            d = Direction(v.isZero() ? Eigen::Vector3d::UnitX() : v);
            break;
        }
        default: {  // along a mid-plane, from a mid-plane
            o.x() = root.center().x();
            d = Direction(0.0, d.y(), d.z());
            break;
        }
        }
        rays.push_back({o, d});
    }
    return rays;
}

TEST(Octree, FirstHitEqualsBruteForceOnMixedScenes) {
    for (int scene = 0; scene < 4; ++scene) {
        SCOPED_TRACE(::testing::Message() << "scene " << scene);
        Rng rng(static_cast<unsigned>(100 + scene));
        const Octree tree(randomScene(rng, 1500, 6.0), OctreeSettings{8, 1 + scene * 3});
        int hits = 0;
        const std::vector<Ray> rays = awkwardRays(rng, tree, 1500);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            SCOPED_TRACE(::testing::Message() << "ray " << i);
            const RayHit expected = bruteForceFirstHit(tree.shapes(), rays[i].origin, rays[i].direction);
            hits += expected ? 1 : 0;
            expectSameHit(tree.firstHit(rays[i].origin, rays[i].direction), expected);
        }
        EXPECT_GT(hits, 500);
    }
}

// The prefilter computes in single precision in a frame scaled to the root (docs/octree.md, "The sphere
// prefilter"): a droplet cloud gives the same hits from 1e-41 to 1e12 scene units across (single precision's
// subnormals below 1e-38, its overflow above 1e38), centred on the origin and 1e3 of its sizes away.
TEST(Octree, FirstHitEqualsBruteForceAtEveryScale) {
    for (const double unit : {1e-41, 1e-20, 1e-6, 1.0, 1e6, 1e12}) {
        for (const double offset : {0.0, 1e3}) {
            SCOPED_TRACE(::testing::Message() << "unit " << unit << ", offset " << offset);
            Rng rng(53);
            const Point centre = Point(offset, -0.7 * offset, 0.3 * offset) * unit;
            std::vector<std::unique_ptr<Shape>> shapes;
            for (int i = 0; i < 600; ++i) {
                const double radius = testing::uniform(rng, 0.005, 0.05) * unit;
                shapes.push_back(std::make_unique<Sphere>(centre + testing::randomPoint(rng, unit), radius));
            }
            const Octree tree(std::move(shapes), OctreeSettings{8, 8});
            int hits = 0;
            for (const Ray& ray : awkwardRays(rng, tree, 1200)) {
                const RayHit expected = bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction);
                hits += expected ? 1 : 0;
                expectSameHit(tree.firstHit(ray.origin, ray.direction), expected);
            }
            EXPECT_GT(hits, 300);
        }
    }
}

// The walk over the top grid (docs/octree.md, "The top grid") must find what the walk from the root finds.
// A droplet cloud fills every cell down to level 3; a box around the cloud stays in the root; a sphere on
// the centre of a level-1 cell reaches all 8 of its children, so it stays in that inner cell, above the
// grid, where only the walk's test of the cells it enters on the way finds it.
TEST(Octree, TopGridWalkEqualsBruteForce) {
    Rng rng(31);
    std::vector<std::unique_ptr<Shape>> shapes = randomSpheres(rng, 4000, 2.0, 0.01, 0.08);
    shapes.push_back(std::make_unique<Box>(Point(-2.1, -2.1, -2.1), Point(2.1, 2.1, 2.1)));  // fixes the root
    const Point straddler = Point::Constant(0.5 * 2.1 * (1.0 + 1e-6));  // centre of the (+, +, +) level-1 cell
    shapes.push_back(std::make_unique<Sphere>(straddler, 0.05));
    const auto straddlerId = static_cast<ShapeId>(shapes.size() - 1);
    const Octree tree(std::move(shapes), OctreeSettings{10, 16});
    ASSERT_EQ(tree.rootBounds().center(), Point::Zero());
    ASSERT_GE(tree.gridLevel(), 3);

    std::vector<Ray> rays = awkwardRays(rng, tree, 6000);
    for (int i = 0; i < 500; ++i) {  // at the straddler from near it, across the inner cell's mid-planes
        const Point from = testing::randomPoint(rng, 0.25, straddler);
        rays.push_back({from, Direction(straddler - from)});
    }
    const std::size_t fromOtherCells = rays.size();
    for (int i = 0; i < 300; ++i) {  // from the neighbouring level-1 cells, entering the straddler's on the way
        Point from = testing::randomPoint(rng, 0.1, straddler);
        from[i % 3] -= 1.1;
        rays.push_back({from, Direction(straddler - from)});
    }
    const std::size_t subnormal = rays.size();
    for (int i = 0; i < 60; ++i) {  // on a grid plane, moving along it by a subnormal component (1/d is inf)
        Point from = testing::randomPoint(rng, 1.8);
        const int axis = i % 3;
        from[axis] = -2.1 * (1.0 + 1e-6) + 4.2 * (1.0 + 1e-6) / 8.0 * static_cast<double>(1 + i % 7);
        Eigen::Vector3d v = testing::randomDirection(rng).vector();
        v[axis] = (i % 2 == 0 ? 1e-320 : -1e-320);
        rays.push_back({from, Direction(v)});
    }
    const double cell = tree.rootBounds().sizes().maxCoeff() / std::pow(2.0, tree.gridLevel());
    for (int i = 0; i < 500; ++i) {  // along the grid's planes and edges, parallel to an axis
        const auto x = static_cast<double>(rng() % 9);
        const auto y = static_cast<double>(rng() % 9);
        const auto z = static_cast<double>(rng() % 9);
        Point o = tree.rootBounds().min().array() + cell * Eigen::Array3d(x, y, z);
        const int axis = static_cast<int>(rng() % 3);
        o[axis] = tree.rootBounds().min()[axis] - 1.0;
        Eigen::Vector3d v = Eigen::Vector3d::Zero();
        v[axis] = 1.0;
        rays.push_back({o, Direction(v)});
    }
    int straddlerHits = 0;
    int straddlerHitsFromOtherCells = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        SCOPED_TRACE(::testing::Message() << "ray " << i);
        const RayHit expected = bruteForceFirstHit(tree.shapes(), rays[i].origin, rays[i].direction);
        straddlerHits += expected.shape == straddlerId ? 1 : 0;
        straddlerHitsFromOtherCells += expected.shape == straddlerId && i >= fromOtherCells && i < subnormal ? 1 : 0;
        expectSameHit(tree.firstHit(rays[i].origin, rays[i].direction), expected);
        TraversalRecord record;  // the walk from the root, every level
        expectSameHit(tree.firstHit(rays[i].origin, rays[i].direction, record), expected);
    }
    EXPECT_GT(straddlerHits, 300);
    EXPECT_GT(straddlerHitsFromOtherCells, 60);
}

// The grid's last cell along an axis reaches to the inflated root, as the recursive walk's last child does. The
// grid's far face, computed from the root's centre and half-side, can lie an ulp inside the root's face; a ray
// starting there and leaving by a hair must still find a box inserted against the root's face further on. The
// clouds are shifted until the rounding falls that way (about 1 in 12 does).
TEST(Octree, TopGridWalkRunsToTheRootFace) {
    bool found = false;
    for (int shift = 0; shift < 400 && !found; ++shift) {
        Rng rng(static_cast<unsigned>(33 + shift));
        const Point offset = testing::randomPoint(rng, 5.0);
        Octree tree(randomSpheres(rng, 3000, 2.0, 0.01, 0.06, offset), OctreeSettings{10, 16});
        if (tree.gridLevel() < 2) continue;
        const CellBounds root = tree.rootBounds();
        const auto [low, cell, side] = gridGeometry(root, tree.gridLevel());
        const double face = low.x() + cell * side;
        if (!(face < root.max().x())) continue;
        found = true;
        const double y = low.y() + cell * (side / 2);
        const double z = low.z() + cell * (side / 2 + 0.5);
        const ShapeId box = tree.insert(std::make_unique<Box>(Point(root.max().x() - 0.05, y + 0.1, z - 0.1),
                                                              Point(root.max().x(), y + 0.2, z + 0.1)));
        ASSERT_TRUE(tree.rootBounds().isApprox(root, 0.0));  // inside: placed, not rebuilt
        const Point origin(face, y - 0.5 * cell, z);
        const Direction along(1e-18, 1.0, 0.0);
        const RayHit expected = bruteForceFirstHit(tree.shapes(), origin, along);
        EXPECT_EQ(expected.shape, box);
        expectSameHit(tree.firstHit(origin, along), expected);
    }
    EXPECT_TRUE(found);
}

// The grid walk visits every grid cell a ray passes through, also the corner of a cell that it clips beside an
// edge of the grid. Probes: a small sphere in each of the four cells around an edge, a thousandth of a cell
// from both planes (so, across the edge, stored in that cell alone), each traced both ways along the line
// through it across the cell's corner, from 3 thousandths before it: each ray enters the probe's cell across
// one plane and leaves it across the other, 2 thousandths of a cell apart. A walk with one plane off by 2
// thousandths of a cell (0.2 %) or more, or that took the crossings in the wrong order, would skip the cell.
TEST(Octree, TopGridWalkEntersEveryCellItClips) {
    Rng rng(37);
    std::vector<std::unique_ptr<Shape>> cloud = randomSpheres(rng, 4000, 2.0, 0.01, 0.08);
    cloud.push_back(std::make_unique<Box>(Point(-2.1, -2.1, -2.1), Point(2.1, 2.1, 2.1)));  // fixes the root
    const Octree withoutProbes(copies(cloud), OctreeSettings{10, 16});
    const int gridLevel = withoutProbes.gridLevel();
    ASSERT_GE(gridLevel, 3);
    const CellBounds root = withoutProbes.rootBounds();
    const auto [low, cell, side] = gridGeometry(root, gridLevel);
    const double apart = 1e-3 * cell;  // a probe's centre from each of the edge's two planes
    const double lead = 3e-3 * cell;   // how far before the probe a ray starts, along each of the two axes

    std::vector<std::unique_ptr<Shape>> shapes = copies(cloud);
    std::vector<Ray> rays;
    std::vector<ShapeId> probes;
    for (int edge = 0; edge < 120; ++edge) {
        const int along = edge % 3;  // the edge's axis; a and b span its cross-section
        const int a = (along + 1) % 3;
        const int b = (along + 2) % 3;
        Point corner;
        corner[a] = low[a] + cell * static_cast<double>(1 + rng() % static_cast<unsigned>(side - 1));
        corner[b] = low[b] + cell * static_cast<double>(1 + rng() % static_cast<unsigned>(side - 1));
        corner[along] = testing::uniform(rng, -1.9, 1.9);
        for (int quadrant = 0; quadrant < 4; ++quadrant) {
            const double sa = (quadrant & 1) ? 1.0 : -1.0;
            const double sb = (quadrant & 2) ? 1.0 : -1.0;
            Point centre = corner;
            centre[a] += sa * apart;
            centre[b] += sb * apart;
            shapes.push_back(std::make_unique<Sphere>(centre, 0.5 * apart));
            const auto probe = static_cast<ShapeId>(shapes.size() - 1);
            // From the quadrant across a's plane, and from the one across b's.
            for (const auto& [ua, ub] : {std::pair{-sa, sb}, std::pair{sa, -sb}}) {
                Eigen::Vector3d toward = Eigen::Vector3d::Zero();
                toward[a] = -ua;
                toward[b] = -ub;
                toward[along] = testing::uniform(rng, -0.5, 0.5);
                Point from = centre;
                from[a] += ua * lead;
                from[b] += ub * lead;
                from[along] -= toward[along] * lead;
                rays.push_back({from, Direction(toward)});
                probes.push_back(probe);
            }
        }
    }
    const Octree tree(std::move(shapes), OctreeSettings{10, 16});
    ASSERT_EQ(tree.gridLevel(), gridLevel);
    ASSERT_TRUE(tree.rootBounds().isApprox(root, 0.0));
    int probeHits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        SCOPED_TRACE(::testing::Message() << "ray " << i);
        const RayHit expected = bruteForceFirstHit(tree.shapes(), rays[i].origin, rays[i].direction);
        probeHits += expected.shape == probes[i] ? 1 : 0;
        expectSameHit(tree.firstHit(rays[i].origin, rays[i].direction), expected);
    }
    EXPECT_GT(probeHits, static_cast<int>(rays.size()) * 9 / 10);
}

// In a small tree the prefilter reads on past a cell's own sphere blocks into the next cells' (docs/octree.md,
// "A fixed number of lanes in a small tree"), never past the end of the block array: clouds of leaves of at most
// 32 spheres (whose read-ahead reaches furthest, to the last float of the 8th block), of many sizes, so that
// cells of every size start at every distance from the array's end, traced at every droplet from outside and
// from its centre outwards. Under AddressSanitizer a read past the array fails here.
TEST(Octree, ThePrefilterReadsAheadNoFurtherThanTheLastBlock) {
    for (int count = 20; count <= 300; count += 7) {
        SCOPED_TRACE(::testing::Message() << count << " droplets");
        Rng rng(static_cast<unsigned>(500 + count));
        const Octree tree(randomSpheres(rng, count, 1.0, 0.02, 0.1), OctreeSettings{6, 32});
        std::vector<Ray> rays;
        for (const auto& shape : tree.shapes()) {
            const Point centre = testing::boundsCenter(*shape);
            const Point from = centre + 3.0 * testing::randomDirection(rng).vector();
            rays.push_back({from, Direction(centre - from)});
            rays.push_back({centre, testing::randomDirection(rng)});
        }
        int hits = 0;
        for (const Ray& ray : rays) {
            const RayHit expected = bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction);
            hits += expected ? 1 : 0;
            expectSameHit(tree.firstHit(ray.origin, ray.direction), expected);
        }
        EXPECT_GE(hits, 2 * count);
    }
}

// A cell of more than 64 spheres goes through the prefilter in groups of 64 from lane `first` of its arrays, each
// with its own ids: one leaf of every size around the groups' edges, traced at every droplet from outside and
// from its centre outwards, equals brute force.
TEST(Octree, ALeafOfMoreThan64SpheresEqualsBruteForce) {
    for (int count : {63, 64, 65, 67, 96, 127, 128, 129, 130, 160, 193, 250}) {
        SCOPED_TRACE(::testing::Message() << count << " droplets");
        Rng rng(static_cast<unsigned>(900 + count));
        std::vector<std::unique_ptr<Shape>> shapes;
        for (int i = 0; i < count; ++i) {
            shapes.push_back(
                std::make_unique<Sphere>(testing::randomPoint(rng, 1.0), testing::uniform(rng, 0.02, 0.1)));
        }
        const Octree tree(std::move(shapes), OctreeSettings{6, 1000});
        ASSERT_EQ(tree.statistics().size(), 1u);  // the root alone, a leaf
        int hits = 0;
        for (const auto& shape : tree.shapes()) {
            const Point centre = testing::boundsCenter(*shape);
            const Point from = centre + 3.0 * testing::randomDirection(rng).vector();
            for (const Ray& ray : {Ray{from, Direction(centre - from)}, Ray{centre, testing::randomDirection(rng)}}) {
                const RayHit expected = bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction);
                hits += expected ? 1 : 0;
                expectSameHit(tree.firstHit(ray.origin, ray.direction), expected);
            }
        }
        EXPECT_GE(hits, 2 * count);
    }
}

// A ray from strictly inside the inflated root enters it at exactly +0 whatever its direction, which the walk
// takes for granted there (it starts from p without waiting on the clip): one ulp inside each face, moving
// along, across and away from it, with components of +-0 and subnormal ones (whose inverse is infinite).
TEST(Octree, ARayFromJustInsideTheRootEntersItAtZero) {
    Rng rng(61);
    const Octree tree(randomSpheres(rng, 600, 1.0, 0.02, 0.06), OctreeSettings{10, 16});
    ASSERT_GT(tree.gridLevel(), 0);
    const Eigen::Array3d low = tree.rootBounds().min().array() - tree.margin();
    const Eigen::Array3d high = tree.rootBounds().max().array() + tree.margin();
    const double tiny = std::numeric_limits<double>::denorm_min() * 1e3;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    int rays = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (const bool upper : {false, true}) {
            for (int i = 0; i < 40; ++i) {
                Point p = testing::randomPoint(rng, 0.9);
                p[axis] = upper ? std::nextafter(high[axis], -kInfinity) : std::nextafter(low[axis], kInfinity);
                Eigen::Vector3d v = testing::randomDirection(rng).vector();
                switch (i % 5) {
                case 0:  // across the face, inwards or outwards
                    v = Eigen::Vector3d::Zero();
                    v[axis] = i % 2 == 0 ? 1.0 : -1.0;
                    break;
                case 1: v[axis] = i % 2 == 0 ? 0.0 : -0.0; break;    // along it
                case 2: v[axis] = i % 2 == 0 ? tiny : -tiny; break;  // along it, subnormally
                case 3:                                              // -0 and subnormal across the other two axes
                    v[(axis + 1) % 3] = -0.0;
                    v[(axis + 2) % 3] = tiny;
                    break;
                default: break;
                }
                const Direction d(v);
                ASSERT_TRUE(d);
                SCOPED_TRACE(::testing::Message() << "axis " << axis << ", upper " << upper << ", ray " << i);
                const auto span = tree.rootSpan(p, d);
                ASSERT_TRUE(span.has_value());
                EXPECT_EQ(span->first, 0.0);
                EXPECT_FALSE(std::signbit(span->first));
                EXPECT_GT(span->second, 0.0);
                const RayHit expected = bruteForceFirstHit(tree.shapes(), p, d);
                expectSameHit(tree.firstHit(p, d), expected);
                TraversalRecord record;
                expectSameHit(tree.firstHit(p, d, record), expected);
                ++rays;
            }
        }
    }
    EXPECT_EQ(rays, 240);
}

TEST(Octree, NoTopGridWhereALevelHasLeaves) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(-7, -7, -7), 0.5));
    shapes.push_back(std::make_unique<Sphere>(Point(7, 7, 7), 0.5));
    EXPECT_EQ(Octree(std::move(shapes), OctreeSettings{8, 1}).gridLevel(), 0);
}

TEST(Octree, ReferenceTreeEqualsBruteForceAndRespectsTheSeedModel) {
    Rng rng(7);
    const Octree tree(randomScene(rng, 600, 4.0), OctreeSettings{6, 4});
    const auto reference = tree.referenceTree();
    // Every live shape appears as a terminal child; no box holds more than 8 children.
    std::vector<int> seen(tree.slotCount(), 0);
    std::vector<const BoundingBox*> pending{reference.get()};
    while (!pending.empty()) {
        const BoundingBox* box = pending.back();
        pending.pop_back();
        ASSERT_LE(box->childCount(), BoundingBox::kMaxChildren);
        for (std::size_t k = 0; k < box->childCount(); ++k) {
            if (box->childId(k) == BoundingBox::kNotTerminal) {
                pending.push_back(&static_cast<const BoundingBox&>(box->child(k)));
            } else {
                ++seen[box->childId(k)];
            }
        }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n > 0; }));
    for (const Ray& ray : awkwardRays(rng, tree, 800)) {
        expectSameHit(reference->firstHit(ray.origin, ray.direction, tree.margin()),
                      bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction));
    }
}

TEST(Octree, ContentsOverlapFindsStoredShapes) {
    Rng rng(8);
    const Octree tree(randomScene(rng, 200, 4.0));
    const auto reference = tree.referenceTree();
    for (int i = 0; i < 200; ++i) {
        const Sphere probe(testing::randomPoint(rng, 5.0), testing::uniform(rng, 0.05, 0.5));
        const bool expected =
            std::any_of(tree.shapes().begin(), tree.shapes().end(), [&](const auto& s) { return s->overlaps(probe); });
        EXPECT_EQ(reference->contentsOverlap(probe), expected);
    }
}

TEST(Octree, LocateFindsTheInnermostEnclosingShape) {
    Rng rng(9);
    std::vector<std::unique_ptr<Shape>> shapes = randomScene(rng, 800, 4.0);
    shapes.push_back(std::make_unique<Box>(Point(-5, -5, -5), Point(5, 5, 0)));  // encloses many
    const Octree tree(std::move(shapes));
    for (int i = 0; i < 3000; ++i) {
        const Point p = testing::randomPoint(rng, 5.5);
        std::optional<ShapeId> expected;
        for (ShapeId id = 0; id < tree.slotCount(); ++id) {
            const Shape& s = *tree.shape(id);
            if (s.encloses(p) && (!expected || s.volume() < tree.shape(*expected)->volume())) expected = id;
        }
        EXPECT_EQ(tree.locate(p), expected) << "point " << i;
    }
}

// OpticalScene::findContainers walks one point's path for every shape centred in its leaf.
TEST(Octree, PointsInOneLeafHaveOnePath) {
    Rng rng(19);
    const Octree tree(randomScene(rng, 800, 4.0), OctreeSettings{8, 4});
    std::map<std::uint32_t, std::vector<ShapeId>> pathOfLeaf;
    int shared = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point p = testing::randomPoint(rng, 4.0);
        const std::optional<std::uint32_t> leaf = tree.leafHolding(p);
        ASSERT_TRUE(leaf) << "point " << i;
        std::vector<ShapeId> path;
        tree.forEachShapeAlongPath(p, [&](ShapeId id) { path.push_back(id); });
        const auto [known, fresh] = pathOfLeaf.try_emplace(*leaf, path);
        if (!fresh) {
            ++shared;
            ASSERT_EQ(path, known->second) << "point " << i << ", leaf " << *leaf;
        }
    }
    EXPECT_GE(pathOfLeaf.size(), 200u);
    EXPECT_GE(shared, 10000);
    EXPECT_FALSE(tree.leafHolding(Point(1e3, 0, 0)));
    EXPECT_FALSE(tree.leafHolding(Point(std::numeric_limits<double>::quiet_NaN(), 0, 0)));
}

// Every cell, and the shapes each holds in their order, as visitCells and the paths to the leaves give them:
// what the queries can see of a tree, the cells' numbering aside.
struct TreeContents {
    std::vector<std::tuple<std::array<double, 6>, int, bool, std::size_t>> cells;  // min, max, level, leaf, count
    std::vector<std::vector<ShapeId>> leafPaths;
};

TreeContents contentsOf(const Octree& tree) {
    TreeContents contents;
    tree.visitCells([&](const CellBounds& bounds, int level, bool leaf, std::size_t stored) {
        const std::array<double, 6> corners{bounds.min().x(), bounds.min().y(), bounds.min().z(),
                                            bounds.max().x(), bounds.max().y(), bounds.max().z()};
        contents.cells.emplace_back(corners, level, leaf, stored);
        if (leaf) {
            std::vector<ShapeId>& path = contents.leafPaths.emplace_back();
            tree.forEachShapeAlongPath(bounds.center(), [&](ShapeId id) { path.push_back(id); });
        }
        return true;
    });
    return contents;
}

void expectSameTree(const Octree& actual, const Octree& expected) {
    const TreeContents expectedContents = contentsOf(expected);
    const TreeContents actualContents = contentsOf(actual);
    EXPECT_TRUE(actualContents.cells == expectedContents.cells);
    EXPECT_TRUE(actualContents.leafPaths == expectedContents.leafPaths);
    EXPECT_EQ(actual.margin(), expected.margin());
    EXPECT_EQ(actual.gridLevel(), expected.gridLevel());
}

// The top-down build makes the tree that placing the shapes one by one makes: the same cells, each holding the
// same shapes in the same order, whatever the leaf size and depth limit; with boxes, ellipsoids, a sphere and a
// box reaching every cell (kept high up), coincident spheres, spheres on the root's mid-planes, spheres and boxes
// reaching across a mid-plane by less than the margin or just beyond it, and empty slots.
TEST(Octree, TheTopDownBuildMakesTheTreeOfTheOneByOneBuild) {
    Rng rng(23);
    std::vector<std::unique_ptr<Shape>> shapes = randomScene(rng, 1500, 4.0);
    shapes.push_back(std::make_unique<Sphere>(Point(0.0, 0.0, 0.0), 9.0));
    shapes.push_back(std::make_unique<Box>(Point(-3.0, -3.0, -3.0), Point(3.0, 3.0, 3.0)));
    for (int k = 0; k < 40; ++k) shapes.push_back(std::make_unique<Sphere>(Point(1.0, 1.0, 1.0), 0.1));
    for (int k = 0; k < 40; ++k) {
        shapes.push_back(std::make_unique<Sphere>(Point(0.0, testing::uniform(rng, -4.0, 4.0), 0.0), 0.05));
    }
    // These reach past the plane x = 0 (a mid-plane of the root, which the big sphere centres there, and of its
    // children) by a tenth of the margin cells are grown by, or stop a tenth of it short, at many places: a build
    // that tested the cells without their margin would store them elsewhere.
    const double margin = Octree(copies(shapes)).margin();
    for (int k = 0; k < 60; ++k) {
        const double y = testing::uniform(rng, -4.0, 4.0);
        const double z = testing::uniform(rng, -4.0, 4.0);
        const double reach = (k % 2 == 0 ? 0.1 : -0.1) * margin;
        shapes.push_back(std::make_unique<Sphere>(Point(0.05 - reach, y, z), 0.05));
        shapes.push_back(std::make_unique<Box>(Point(-0.1, y, z), Point(-reach, y + 0.05, z + 0.05)));
    }
    for (std::size_t id = 3; id < shapes.size(); id += 97) shapes[id].reset();
    for (const OctreeSettings settings :
         {OctreeSettings{}, OctreeSettings{10, 4}, OctreeSettings{3, 2}, OctreeSettings{0, 8}, OctreeSettings{12, 1}}) {
        SCOPED_TRACE("max depth " + std::to_string(settings.maxDepth) + ", leaf " +
                     std::to_string(settings.maxShapesPerLeaf));
        const Octree topDown(copies(shapes), settings);
        const Octree oneByOne(copies(shapes), settings, OctreeBuild::OneByOne);
        EXPECT_GT(contentsOf(oneByOne).cells.size(), settings.maxDepth > 0 ? 8U : 0U);
        expectSameTree(topDown, oneByOne);
    }
    // Built again as the root grows: a shape inserted beyond it, into trees with empty slots.
    Octree topDown(copies(shapes), OctreeSettings{10, 4});
    Octree oneByOne(copies(shapes), OctreeSettings{10, 4}, OctreeBuild::OneByOne);
    for (Octree* tree : {&topDown, &oneByOne}) tree->insert(std::make_unique<Sphere>(Point(30.0, 0.0, 0.0), 1.0));
    EXPECT_GT(topDown.rootBounds().max().x(), 30.0);
    expectSameTree(topDown, oneByOne);
}

TEST(Octree, OverlappingEqualsBruteForce) {
    Rng rng(10);
    const Octree tree(randomScene(rng, 800, 4.0));
    for (int i = 0; i < 300; ++i) {
        const auto probe =
            testing::randomShape(rng, i, testing::randomPoint(rng, 4.5), testing::uniform(rng, 0.05, 1.0));
        std::vector<ShapeId> expected;
        for (ShapeId id = 0; id < tree.slotCount(); ++id) {
            if (tree.shape(id)->overlaps(*probe)) expected.push_back(id);
        }
        EXPECT_EQ(tree.overlapping(*probe), expected) << "probe " << i;
    }
}

TEST(Octree, InsertAndRemoveKeepQueriesExact) {
    Rng rng(11);
    Octree tree(randomScene(rng, 300, 3.0), OctreeSettings{7, 3});
    std::vector<ShapeId> live;
    for (ShapeId id = 0; id < tree.slotCount(); ++id) live.push_back(id);
    for (int step = 0; step < 400; ++step) {
        SCOPED_TRACE(::testing::Message() << "step " << step);
        if (rng() % 3 == 0 && !live.empty()) {
            const std::size_t k = rng() % live.size();
            ASSERT_NE(tree.remove(live[k]), nullptr);
            live.erase(live.begin() + static_cast<std::ptrdiff_t>(k));
        } else {
            // now and then far outside the current root, which must grow
            const double reach = step % 50 == 0 ? 9.0 : 3.0;
            live.push_back(tree.insert(testing::randomShape(rng, step, testing::randomPoint(rng, reach), 0.3)));
        }
        ASSERT_EQ(tree.shapeCount(), live.size());
        for (const Ray& ray : awkwardRays(rng, tree, 6)) {
            expectSameHit(tree.firstHit(ray.origin, ray.direction),
                          bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction));
        }
    }
    for (const Ray& ray : awkwardRays(rng, tree, 1000)) {
        expectSameHit(tree.firstHit(ray.origin, ray.direction),
                      bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction));
    }
}

// The octree's own copy of each sphere is what the tracer reads for a hit sphere (OpticalScene): the Sphere's
// geometry to the bit, band included; no other shape and no emptied slot is a packed sphere.
TEST(Octree, PackedSpheresAreTheSpheresOwnGeometry) {
    Rng rng(12);
    Octree tree(randomScene(rng, 400, 3.0), OctreeSettings{7, 3});
    const auto expectPacked = [&] {
        int spheres = 0;
        for (ShapeId id = 0; id < tree.slotCount(); ++id) {
            const auto* sphere = dynamic_cast<const Sphere*>(tree.shape(id));
            ASSERT_EQ(tree.packsSphere(id), sphere != nullptr) << "shape " << id;
            if (!sphere) continue;
            ++spheres;
            const SphereGeometry packed = tree.packedSphere(id);
            EXPECT_EQ(packed.center, sphere->geometry().center) << "shape " << id;
            EXPECT_EQ(packed.radius, sphere->geometry().radius) << "shape " << id;
            EXPECT_EQ(packed.band, sphere->geometry().band) << "shape " << id;
        }
        EXPECT_GT(spheres, 50);
        EXPECT_FALSE(tree.packsSphere(static_cast<ShapeId>(tree.slotCount())));
    };
    expectPacked();
    for (ShapeId id = 0; id < tree.slotCount(); id += 3) ASSERT_NE(tree.remove(id), nullptr);
    expectPacked();
    tree.insert(std::make_unique<Sphere>(Point(20.0, -3.0, 1.0), 0.25));  // the root grows, the frame with it
    expectPacked();
}

TEST(Octree, TraversalRecordListsCellsInRayOrder) {
    Rng rng(12);
    const Octree tree(randomScene(rng, 1000, 5.0));
    for (const Ray& ray : awkwardRays(rng, tree, 300)) {
        TraversalRecord record;
        const RayHit hit = tree.firstHit(ray.origin, ray.direction, record);
        expectSameHit(record.hit, hit);
        expectSameHit(hit, bruteForceFirstHit(tree.shapes(), ray.origin, ray.direction));
        EXPECT_EQ(record.distanceEvaluations, record.shapesTested.size());
        if (hit) {
            EXPECT_NE(std::find(record.shapesTested.begin(), record.shapesTested.end(), hit.shape),
                      record.shapesTested.end());
        }
        for (std::size_t k = 0; k + 1 < record.cells.size(); ++k) {
            EXPECT_LE(record.cells[k].tEnter, record.cells[k + 1].tEnter);
            const double expectedSize = tree.rootBounds().sizes().maxCoeff() / std::pow(2.0, record.cells[k].level);
            EXPECT_NEAR(record.cells[k].bounds.sizes().maxCoeff(), expectedSize, 1e-12 * expectedSize);
        }
    }
}

TEST(Octree, StatisticsAreConsistent) {
    Rng rng(13);
    const OctreeSettings settings{6, 5};
    const Octree tree(randomScene(rng, 2000, 5.0), settings);
    const std::vector<LevelStatistics> levels = tree.statistics();
    ASSERT_FALSE(levels.empty());
    EXPECT_EQ(levels[0].cells, 1u);
    EXPECT_LE(static_cast<int>(levels.size()), settings.maxDepth + 1);
    std::size_t stored = 0;
    std::size_t bytes = 0;
    for (std::size_t level = 0; level < levels.size(); ++level) {
        const LevelStatistics& s = levels[level];
        if (level > 0) {
            EXPECT_EQ(s.cells, 8 * (levels[level - 1].cells - levels[level - 1].leaves));
        }
        std::size_t leaves = 0;
        std::size_t inLeaves = 0;
        for (std::size_t k = 0; k < s.shapesPerLeaf.size(); ++k) {
            leaves += s.shapesPerLeaf[k];
            inLeaves += k * s.shapesPerLeaf[k];
            if (static_cast<int>(level) < settings.maxDepth && k > 5) {
                EXPECT_EQ(s.shapesPerLeaf[k], 0u);
            }
        }
        EXPECT_EQ(leaves, s.leaves);
        EXPECT_LE(inLeaves, s.shapesStored);
        stored += s.shapesStored;
        bytes += s.bytes;
    }
    EXPECT_GE(stored, tree.shapeCount());
    EXPECT_GT(tree.bytesUsed(), bytes);
}

// Issue 19's budget: index and sphere data within 64 bytes a droplet, besides the 8-byte slot of the shape's
// pointer, in a cloud as dense as the benchmark's (radii 0.002-0.005 at 2.7 % of the volume) at 1e3 droplets,
// where padding and cells weigh most.
TEST(Octree, ACloudTakesAtMost64BytesADropletBesidesItsShapeSlots) {
    Rng rng(41);
    constexpr std::size_t kCount = 1000;
    const Octree tree(randomSpheres(rng, static_cast<int>(kCount), 0.1, 0.002, 0.005));
    const double perDroplet = static_cast<double>(tree.bytesUsed()) / static_cast<double>(kCount);
    EXPECT_LE(perDroplet - sizeof(std::unique_ptr<Shape>), 64.0) << perDroplet;
    EXPECT_GT(perDroplet, 40.0);  // 32 bytes of exact sphere and 1.3 references of 20 at least
}

// A sphere reaching across a cell boundary by less than its surface band does not "overlap" the
// neighbouring cell, yet a ray running inside that cell, closer to the boundary still, does hit it.
// Only the cell margin keeps it from being skipped by the early exit.
TEST(Octree, ShapeReachingIntoACellByLessThanItsBandIsStillFound) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(-7, -7, -7), 0.5));  // these two fix the root around 0,
    shapes.push_back(std::make_unique<Sphere>(Point(7, 7, 7), 0.5));     // so x = 0 is a mid-plane
    const Sphere probe(Point(1.0, 0.0, 0.0), 1.0);
    const double reach = 0.4 * probe.surfaceBand();
    shapes.push_back(std::make_unique<Sphere>(Point(1.0 - reach, 0.0, 0.0), 1.0));  // reaches x = -reach
    shapes.push_back(std::make_unique<Sphere>(Point(-0.5, 3.0, 0.0), 1.0));         // further along the ray
    const Octree tree(std::move(shapes), OctreeSettings{8, 1});
    ASSERT_EQ(tree.rootBounds().center().x(), 0.0);
    const Point origin(-0.5 * reach, -5.0, 0.0);
    const Direction up(0.0, 1.0, 0.0);
    const RayHit expected = bruteForceFirstHit(tree.shapes(), origin, up);
    ASSERT_EQ(expected.shape, 2u);
    expectSameHit(tree.firstHit(origin, up), expected);
}

TEST(Octree, NoShapesNoHits) {
    const Octree tree({});
    EXPECT_FALSE(tree.firstHit(Point::Zero(), Direction(1, 0, 0)));
    EXPECT_FALSE(tree.locate(Point::Zero()));
}

TEST(Octree, InvalidRayHitsNothing) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point::Zero(), 1.0));
    const Octree tree(std::move(shapes));
    EXPECT_FALSE(tree.firstHit(Point(0, 0, -5), Direction(0, 0, 0)));
    EXPECT_FALSE(tree.firstHit(Point(0, std::nan(""), -5), Direction(0, 0, 1)));
    const RayHit hit = tree.firstHit(Point(0, 0, -5), Direction(0, 0, 1));
    EXPECT_EQ(hit.shape, 0u);
    EXPECT_EQ(hit.distance, 4.0);
}

}  // namespace
}  // namespace dropscope
