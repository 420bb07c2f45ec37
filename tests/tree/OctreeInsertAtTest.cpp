// Octree::insertAt: a shape put back into the empty slot remove() left, placed exactly as insert would.
#include "tree/Octree.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using testing::Rng;

std::vector<std::unique_ptr<Shape>> clones(const std::vector<std::unique_ptr<Shape>>& shapes) {
    std::vector<std::unique_ptr<Shape>> copies;
    for (const auto& s : shapes) copies.push_back(s ? s->clone() : nullptr);
    return copies;
}

// The edited octree answers every ray exactly (same id, same double) as a fresh one over the same slots,
// and as brute force.
void expectSameAnswers(const Octree& edited, Rng& rng, int rays) {
    const Octree fresh(clones(edited.shapes()), edited.settings());
    ASSERT_EQ(fresh.shapeCount(), edited.shapeCount());
    const double reach = 0.6 * edited.rootBounds().sizes().maxCoeff();
    for (int i = 0; i < rays; ++i) {
        Point origin = testing::randomPoint(rng, reach, edited.rootBounds().center());
        if (i % 3 == 0) {  // from inside a shape
            const Shape* s = edited.shape(static_cast<ShapeId>(rng() % edited.slotCount()));
            if (s) origin = testing::boundsCenter(*s);  // removed slots are empty
        }
        const Direction d = testing::randomDirection(rng);
        const RayHit expected = fresh.firstHit(origin, d);
        const RayHit actual = edited.firstHit(origin, d);
        ASSERT_EQ(actual.shape, expected.shape) << "ray " << i;
        if (expected) {
            ASSERT_EQ(actual.distance, expected.distance) << "ray " << i;
        }
        const RayHit brute = bruteForceFirstHit(edited.shapes(), origin, d);
        ASSERT_EQ(actual.shape, brute.shape) << "ray " << i;
    }
}

TEST(OctreeInsertAt, RemoveThenInsertAtAnswersLikeAFreshOctree) {
    for (int c = 0; c < 6; ++c) {
        SCOPED_TRACE("case " + std::to_string(c));
        Rng rng(static_cast<std::uint64_t>(c));
        std::vector<std::unique_ptr<Shape>> shapes;
        for (int i = 0; i < 300; ++i) {
            const double size = testing::uniform(rng, 0.05, 0.6);
            shapes.push_back(testing::randomShape(rng, i, testing::randomPoint(rng, 10.0), size));
        }
        Octree tree(std::move(shapes), {10, 1 + c % 6});
        // Take out a third of the shapes; put some back where they were, others moved (some outside
        // the root, which grows it), leave the rest empty.
        std::vector<ShapeId> removed;
        std::vector<std::unique_ptr<Shape>> taken;
        for (ShapeId id = 0; id < tree.slotCount(); id += 3) {
            taken.push_back(tree.remove(id));
            removed.push_back(id);
        }
        expectSameAnswers(tree, rng, 200);
        for (std::size_t k = 0; k < removed.size(); ++k) {
            if (k % 4 == 3) continue;  // stays empty
            std::unique_ptr<Shape> shape = std::move(taken[k]);
            if (k % 4 == 1) {  // a new shape, reaching beyond the root for every 10th
                const double reach = k % 40 == 1 ? 40.0 : 10.0;
                shape = testing::randomShape(rng, static_cast<int>(k), testing::randomPoint(rng, reach), 0.3);
            }
            tree.insertAt(removed[k], std::move(shape));
            ASSERT_NE(tree.shape(removed[k]), nullptr);
        }
        EXPECT_EQ(tree.slotCount(), 300u);
        expectSameAnswers(tree, rng, 400);
    }
}

TEST(OctreeInsertAt, RefusesOccupiedMissingSlotsAndNull) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point::Zero(), 1.0));
    shapes.push_back(std::make_unique<Sphere>(Point(3.0, 0.0, 0.0), 1.0));
    Octree tree(std::move(shapes));
    EXPECT_THROW(tree.insertAt(0, std::make_unique<Sphere>(Point(6.0, 0.0, 0.0), 1.0)), std::invalid_argument);
    EXPECT_THROW(tree.insertAt(2, std::make_unique<Sphere>(Point(6.0, 0.0, 0.0), 1.0)), std::invalid_argument);
    tree.remove(1);
    EXPECT_THROW(tree.insertAt(1, nullptr), std::invalid_argument);
    EXPECT_EQ(tree.slotCount(), 2u);
    EXPECT_EQ(tree.shapeCount(), 1u);
    tree.insertAt(1, std::make_unique<Sphere>(Point(6.0, 0.0, 0.0), 1.0));
    EXPECT_EQ(tree.shapeCount(), 2u);
    EXPECT_EQ(tree.firstHit(Point(10.0, 0.0, 0.0), Direction(-1.0, 0.0, 0.0)).shape, 1u);
    // insert still appends a new slot.
    EXPECT_EQ(tree.insert(std::make_unique<Sphere>(Point(0.0, 5.0, 0.0), 1.0)), 2u);
}

}  // namespace
}  // namespace dropscope
