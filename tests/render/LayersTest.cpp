// The draw layers (render/Layers.hpp) as data, no GL: which cells, segments and markers each one adds,
// where, and in which colour (docs/rendering.md).
#include "geometry/Sphere.hpp"
#include "render/Layers.hpp"
#include "scene/SceneLoader.hpp"
#include "transport/OpticalScene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using render::Colour;
using render::LineBatch;
using render::LineVertex;

const std::string kCloudScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/cloud.json";
const std::string kDefaultScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";

constexpr std::size_t kBoxVertices = 24;  // 12 edges, two vertices each

Point worldOf(const LineVertex& vertex, const render::Anchor& anchor) {
    return anchor.origin + Point(vertex.position[0], vertex.position[1], vertex.position[2]);
}

void expectColour(const Colour& actual, const Colour& expected) {
    for (std::size_t k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(actual[k], expected[k]) << "channel " << k;
}

struct CellCounts {
    std::map<int, std::size_t> perLevel;
    std::size_t leaves = 0;
};

CellCounts countCells(const Octree& octree) {
    CellCounts counts;
    octree.visitCells([&](const CellBounds&, int level, bool leaf, std::size_t) {
        ++counts.perLevel[level];
        if (leaf) ++counts.leaves;
        return true;
    });
    return counts;
}

class LayersOnCloud : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        scene_ = new Scene(loadScene(kCloudScene));
        optical_ = new OpticalScene(*scene_);
    }
    static void TearDownTestSuite() {
        delete optical_;
        delete scene_;
    }
    static const Octree& octree() { return optical_->octree(); }
    static Scene* scene_;
    static OpticalScene* optical_;
};
Scene* LayersOnCloud::scene_ = nullptr;
OpticalScene* LayersOnCloud::optical_ = nullptr;

TEST_F(LayersOnCloud, OctreeFiltersDrawTheCellsTheyName) {
    const CellCounts counts = countCells(octree());
    ASSERT_GE(counts.perLevel.size(), 3u);
    using Mode = render::OctreeFilter::Mode;
    const auto boxes = [&](Mode mode, int level) {
        LineBatch lines{render::Anchor{}};
        render::addOctreeCells(lines, octree(), {mode, level, false});
        EXPECT_EQ(lines.vertices().size() % kBoxVertices, 0u);
        return lines.vertices().size() / kBoxVertices;
    };
    std::size_t all = 0;
    for (const auto& [level, cells] : counts.perLevel) all += cells;
    EXPECT_EQ(boxes(Mode::All, 0), all);
    EXPECT_EQ(boxes(Mode::OnlyLevel, 2), counts.perLevel.at(2));
    EXPECT_EQ(boxes(Mode::UpToLevel, 2), counts.perLevel.at(0) + counts.perLevel.at(1) + counts.perLevel.at(2));
    EXPECT_EQ(boxes(Mode::LeavesOnly, 0), counts.leaves);
    EXPECT_EQ(boxes(Mode::OnlyLevel, 40), 0u);
}

TEST_F(LayersOnCloud, OctreeCellsAreColouredByLevelOrOccupancy) {
    LineBatch byLevel{render::Anchor{}};
    render::addOctreeCells(byLevel, octree(), {render::OctreeFilter::Mode::OnlyLevel, 1, false});
    ASSERT_FALSE(byLevel.empty());
    for (const LineVertex& vertex : byLevel.vertices()) expectColour(vertex.colour, render::levelColour(1));

    // Occupancy: viridis of (shapes stored / leaf capacity), cell by cell in visiting order.
    std::vector<Colour> expected;
    const auto capacity = static_cast<double>(octree().settings().maxShapesPerLeaf);
    octree().visitCells([&](const CellBounds&, int, bool leaf, std::size_t stored) {
        if (leaf) expected.push_back(render::viridis(static_cast<double>(stored) / capacity));
        return true;
    });
    LineBatch heat{render::Anchor{}};
    render::addOctreeCells(heat, octree(), {render::OctreeFilter::Mode::LeavesOnly, 0, true});
    ASSERT_EQ(heat.vertices().size(), expected.size() * kBoxVertices);
    for (std::size_t cell = 0; cell < expected.size(); ++cell) {
        expectColour(heat.vertices()[cell * kBoxVertices].colour, expected[cell]);
    }
}

TEST_F(LayersOnCloud, TraversalDrawsEveryVisitedCellAndTheRayToItsHit) {
    const Ray ray{Point(0.05, 0.03, -20.0), Direction(0.0, 0.0, 1.0)};
    const render::RayTraversal traversal = render::traceTraversal(octree(), ray);
    ASSERT_TRUE(traversal.record.hit);
    ASSERT_GT(traversal.record.cells.size(), 3u);
    const render::Anchor anchor{Point(1.0, 2.0, 3.0)};
    LineBatch lines(anchor);
    render::addTraversal(lines, traversal);
    const auto& vertices = lines.vertices();
    ASSERT_EQ(vertices.size(), traversal.record.cells.size() * kBoxVertices + 2);
    for (const LineVertex& vertex : vertices) expectColour(vertex.colour, render::kTraversalColour);
    const Point hit = ray.origin + traversal.record.hit.distance * ray.direction.vector();
    EXPECT_LT((worldOf(vertices[vertices.size() - 2], anchor) - ray.origin).norm(), 1e-5);
    EXPECT_LT((worldOf(vertices.back(), anchor) - hit).norm(), 1e-5);
}

TEST(PathLayer, SegmentsAreColouredByWeightOrByTheEventTheyStartAt) {
    PhotonPath path;
    path.events = {Event{EventType::Emit, Point(0, 0, -5), Direction(0, 0, 1)},
                   Event{EventType::Refract, Point(0, 0, -1), Direction(0, 0, 1)},
                   Event{EventType::Reflect, Point(0, 0, 1), Direction(0, 0, -1)},
                   Event{EventType::Escape, Point(0, 0, -1), Direction(0, 0, -1)}};
    path.events[2].weight = 0.5;
    LineBatch byEvent{render::Anchor{}};
    render::addPhotonPaths(byEvent, {path}, 2.0, render::PathColouring::Event);
    ASSERT_EQ(byEvent.vertices().size(), 8u);  // three segments and the escape's tail
    const EventType starts[] = {EventType::Emit, EventType::Refract, EventType::Reflect, EventType::Escape};
    for (std::size_t k = 0; k < 4; ++k) expectColour(byEvent.vertices()[2 * k].colour, render::eventColour(starts[k]));
    EXPECT_FLOAT_EQ(byEvent.vertices().back().position[2], -3.0f);

    LineBatch byWeight{render::Anchor{}};
    render::addPhotonPaths(byWeight, {path}, 2.0);
    expectColour(byWeight.vertices()[0].colour, render::viridis(1.0));
    expectColour(byWeight.vertices()[4].colour, render::viridis(0.5));
}

TEST(PathLayer, EveryEventGetsAMarkerOfItsTypeAndTheRadiusAsked) {
    PhotonPath path;
    path.events = {Event{EventType::Emit, Point(0, 0, -5), Direction(0, 0, 1)},
                   Event{EventType::Absorb, Point(0, 0, 0.5), Direction(0, 0, 1)}};
    std::vector<render::ShapeInstance> markers;
    render::addEventMarkers(markers, {path, path}, 0.25, render::Anchor{Point(0, 0, 1)});
    ASSERT_EQ(markers.size(), 4u);
    expectColour(markers[1].colour, render::eventColour(EventType::Absorb));
    EXPECT_FLOAT_EQ(markers[1].center[2], -0.5f);
    EXPECT_FLOAT_EQ(markers[1].linear[0], 0.25f);
    EXPECT_FLOAT_EQ(markers[1].linear[4], 0.25f);
    EXPECT_FLOAT_EQ(markers[1].inverseLinear[8], 4.0f);
}

TEST(RayTreeLayer, BranchesAreColouredOnALogScaleHeaviestFirst) {
    Scene scene = loadScene(kDefaultScene);
    const OpticalScene optical(scene);
    const RayTree tree = traceRayTree(optical, Ray{Point(0.3, 0.2, -8.0), Direction(0, 0, 1)}, 1.0, RayTreeSettings{});
    ASSERT_GT(tree.nodes.size(), 10u);
    LineBatch lines{render::Anchor{}};
    render::addRayTree(lines, tree, 1.0);
    ASSERT_FALSE(lines.empty());
    // Heaviest first: the first segment is the emitted ray, at weight 1 (the top of viridis).
    expectColour(lines.vertices().front().colour, render::viridis(1.0));
    EXPECT_LT((worldOf(lines.vertices().front(), render::Anchor{}) - Point(0.3, 0.2, -8.0)).norm(), 1e-6);

    expectColour(render::logWeightColour(1.0), render::viridis(1.0));
    expectColour(render::logWeightColour(1e-3), render::viridis(0.5));
    expectColour(render::logWeightColour(1e-6), render::viridis(0.0));
    expectColour(render::logWeightColour(1e-9), render::viridis(0.0));
    expectColour(render::logWeightColour(0.0), render::viridis(0.0));
}

// A chain of reflections along x: the segment from node k (at x = k) to node k + 1 carries node k's weight, the
// emission's 1 and then weights[k - 1]; the last node is a truncated leaf, so weights.back() is drawn by no segment.
RayTree chainWithWeights(const std::vector<double>& weights) {
    RayTree tree;
    tree.nodes.push_back({Event{EventType::Emit, Point::Zero(), Direction(1, 0, 0)}, -1, 0});
    for (std::size_t k = 0; k < weights.size(); ++k) {
        Event event{EventType::Reflect, Point(static_cast<double>(k + 1), 0, 0), Direction(1, 0, 0)};
        event.weight = weights[k];
        tree.nodes.push_back({event, static_cast<std::int32_t>(k), static_cast<int>(k + 1)});
    }
    tree.nodes.back().event.type = EventType::Truncated;
    return tree;
}

// Where each drawn segment starts (its x), in the order drawn.
std::vector<double> drawnStarts(const RayTree& tree) {
    LineBatch lines{render::Anchor{}};
    render::addRayTree(lines, tree, 1.0);
    std::vector<double> starts;
    for (std::size_t k = 0; k < lines.vertices().size(); k += 2) starts.push_back(worldOf(lines.vertices()[k], {})[0]);
    return starts;
}

// The order in full: every segment heaviest first, equal weights in the tree's order, a weight of 0 last; weights
// that differ only in their lowest bit, or only in their exponent, still ordered.
TEST(RayTreeLayer, SegmentsAreDrawnHeaviestFirstAndEqualWeightsInTheTreesOrder) {
    const double justAboveHalf = std::nextafter(0.5, 1.0);  // differs from 0.5 in its lowest bit only
    const RayTree tree = chainWithWeights({0.5, 1e-3, justAboveHalf, 0.5, 0.0, 0.25, 1e-300, 1e-3, 0.5});
    const std::vector<double> expected{0, 3, 1, 4, 6, 2, 8, 7, 5};  // 1, 0.5 + ulp, 0.5 x 2, 0.25, 1e-3 x 2, 1e-300, 0
    EXPECT_EQ(drawnStarts(tree), expected);
}

// Many ties, against std::stable_sort: 300 weights drawn from a few values (powers of two, whose keys share all
// but one byte, and two others) and some of their own.
TEST(RayTreeLayer, ManyEqualWeightsKeepTheTreesOrderAsAStableSortDoes) {
    const std::vector<double> few{1.0, 0.5, 0.25, 0.125, 0.3, 1e-4};
    std::vector<double> weights;
    for (std::size_t k = 0; k < 300; ++k)
        weights.push_back(k % 7 == 0 ? 1.0 / static_cast<double>(k + 3) : few[(k * 5) % few.size()]);
    std::vector<double> segmentWeights{1.0};  // the emission's, then every weight but the leaf's
    segmentWeights.insert(segmentWeights.end(), weights.begin(), weights.end() - 1);
    std::vector<double> expected(segmentWeights.size());
    for (std::size_t k = 0; k < expected.size(); ++k) expected[k] = static_cast<double>(k);
    std::stable_sort(expected.begin(), expected.end(), [&](double a, double b) {
        return segmentWeights[static_cast<std::size_t>(a)] > segmentWeights[static_cast<std::size_t>(b)];
    });
    EXPECT_EQ(drawnStarts(chainWithWeights(weights)), expected);

    // Powers of two alone: six of the key's eight bytes are the same in every key, and those passes are skipped.
    std::vector<double> powers;
    for (std::size_t k = 0; k < 40; ++k) powers.push_back(std::ldexp(1.0, -static_cast<int>((k * 3) % 5)));
    std::vector<double> powerStarts{0};  // the emission's 1 first; then the 1s, the 0.5s, ..., each in the tree's order
    for (int exponent = 0; exponent < 5; ++exponent) {
        for (std::size_t k = 0; k + 1 < powers.size(); ++k) {
            if (powers[k] == std::ldexp(1.0, -exponent)) powerStarts.push_back(static_cast<double>(k + 1));
        }
    }
    EXPECT_EQ(drawnStarts(chainWithWeights(powers)), powerStarts);
}

TEST(SourceGlyphs, BeamIsAnArrowAndACircleOfItsRadius) {
    Source beam;
    beam.type = SourceType::Beam;
    beam.origin = Point(1, 2, 3);
    beam.direction = Direction(1, 1, 0);
    beam.radius = 0.75;
    LineBatch lines{render::Anchor{}};
    render::addSourceGlyphs(lines, {beam}, 2.0);
    const auto& vertices = lines.vertices();
    ASSERT_EQ(vertices.size(), 2u * (1 + 4 + 48));  // shaft, four head strokes, the circle
    const Point tip = beam.origin + 2.0 * beam.direction.vector();
    EXPECT_LT((worldOf(vertices[1], {}) - tip).norm(), 1e-5);
    for (std::size_t k = 10; k < vertices.size(); ++k) {
        const Eigen::Vector3d offset = worldOf(vertices[k], {}) - beam.origin;
        EXPECT_NEAR(offset.norm(), 0.75, 1e-5);
        EXPECT_NEAR(offset.dot(beam.direction.vector()), 0.0, 1e-5);
    }
    for (const LineVertex& vertex : vertices) expectColour(vertex.colour, render::kSourceColour);
}

TEST(SourceGlyphs, RayIsAnArrowAndPointIsAThreeAxisStar) {
    Source ray;
    ray.type = SourceType::Ray;
    Source point;
    point.type = SourceType::PointSource;
    point.origin = Point(0, 0, 5);
    LineBatch lines{render::Anchor{}};
    render::addSourceGlyphs(lines, {ray, point}, 4.0);
    ASSERT_EQ(lines.vertices().size(), 2u * (5 + 3));
    for (std::size_t k = 10; k < 16; k += 2) {
        const Point a = worldOf(lines.vertices()[k], {});
        const Point b = worldOf(lines.vertices()[k + 1], {});
        EXPECT_LT(((a + b) / 2 - point.origin).norm(), 1e-6);
        EXPECT_NEAR((b - a).norm(), 2.0, 1e-6);
    }
}

TEST(Guides, AxesAreRedGreenBlueFromTheOrigin) {
    LineBatch lines{render::Anchor{}};
    render::addAxes(lines, Point(1, 1, 1), 2.0);
    ASSERT_EQ(lines.vertices().size(), 6u);
    const Colour colours[] = {render::kAxisX, render::kAxisY, render::kAxisZ};
    for (int axis = 0; axis < 3; ++axis) {
        const auto k = static_cast<std::size_t>(2 * axis);
        expectColour(lines.vertices()[k].colour, colours[axis]);
        const Point end = worldOf(lines.vertices()[k + 1], {});
        EXPECT_EQ(end, Point(1, 1, 1) + 2.0 * Eigen::Vector3d::Unit(axis));
    }
}

TEST(Guides, GroundGridLiesUnderTheBoundsAcrossTheUpAxis) {
    const Eigen::AlignedBox3d bounds(Point(-3, -2, -1), Point(5, 4, 1));
    for (const auto& [up, axis, below] :
         {std::tuple{Eigen::Vector3d(0.1, 1.0, 0.2), 1, true}, std::tuple{Eigen::Vector3d(0.0, 0.0, -1.0), 2, false}}) {
        LineBatch lines{render::Anchor{}};
        render::addGroundGrid(lines, bounds, up);
        ASSERT_FALSE(lines.empty());
        double lowest = INFINITY;
        double highest = -INFINITY;
        for (const LineVertex& vertex : lines.vertices()) {
            const Point p = worldOf(vertex, {});
            lowest = std::min(lowest, p[axis]);
            highest = std::max(highest, p[axis]);
        }
        EXPECT_NEAR(lowest, highest, 1e-6) << "the grid is flat";
        if (below) {
            EXPECT_LT(highest, bounds.min()[axis]);
        } else {
            EXPECT_GT(lowest, bounds.max()[axis]);
        }
    }
    // Square, covering the larger extent across the up axis (8 along x) 1.5 times, spacing 1-2-5.
    LineBatch lines{render::Anchor{}};
    render::addGroundGrid(lines, bounds, Eigen::Vector3d::UnitY());
    Eigen::AlignedBox3d covered;
    for (const LineVertex& vertex : lines.vertices()) covered.extend(worldOf(vertex, {}));
    EXPECT_NEAR(covered.sizes().x(), covered.sizes().z(), 1e-6);
    EXPECT_GE(covered.sizes().x(), 12.0 - 1e-6);
    EXPECT_LT(covered.sizes().x(), 12.0 + 2.0 + 1e-6);
}

TEST(SceneLayers, OnlyTheSwitchedOnLayersAreBuiltTraversalFirst) {
    Scene scene = loadScene(kDefaultScene);
    const OpticalScene optical(scene);
    const Eigen::AlignedBox3d bounds = render::sceneBounds(optical.octree().shapes());
    const render::Anchor anchor{bounds.center()};
    const Source& source = scene.sources.front();
    const render::RayTraversal traversal =
        render::traceTraversal(optical.octree(), Ray{source.origin, source.direction});
    render::LayerInputs inputs{optical.octree(), scene.sources, bounds};
    inputs.traversal = &traversal;

    render::LayerOptions options;
    EXPECT_TRUE(render::buildSceneLayers(inputs, options, anchor).lines.empty()) << "nothing but shapes by default";
    EXPECT_TRUE(render::buildSceneLayers(inputs, options, anchor).markers.empty());

    options.octree = true;
    options.traversal = true;
    options.axes = true;
    const render::SceneLayers layers = render::buildSceneLayers(inputs, options, anchor);
    // Traversal first (it wins depth ties with the octree cells it coincides with), then axes, then cells.
    ASSERT_EQ(layers.lines.vertices().size(), traversal.record.cells.size() * kBoxVertices + 2 + 6 + kBoxVertices);
    expectColour(layers.lines.vertices().front().colour, render::kTraversalColour);
    expectColour(layers.lines.vertices().back().colour, render::levelColour(0));
}

}  // namespace
}  // namespace dropscope
