// The slice plane (render/SlicePlane.hpp): segments cut exactly at the plane, shapes and markers kept
// or hidden by their centre, and in a real snapshot only the sphere on the kept side drawn.
#include "render/RenderHarness.hpp"
#include "render/SceneLayers.hpp"
#include "render/SlicePlane.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/Snapshot.hpp"
#include "transport/OpticalScene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace dropscope {
namespace {

using render::Colour;
using render::LineBatch;
using render::LineVertex;
using render::SegmentSpan;
using render::SlicePlane;

const std::string kDefaultScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";
const std::string kCloudScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/cloud.json";

// The plane x = 0.5 hiding x > 0.5.
const SlicePlane kPlaneX{Point(0.5, 0.0, 0.0), Direction(1.0, 0.0, 0.0)};

Point positionOf(const LineVertex& vertex, const render::Anchor& anchor) {
    return anchor.origin + Point(vertex.position[0], vertex.position[1], vertex.position[2]);
}

void expectColour(const Colour& actual, const Colour& expected) {
    for (std::size_t k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(actual[k], expected[k]) << "channel " << k;
}

void expectSpan(const std::optional<SegmentSpan>& span, double from, double to) {
    ASSERT_TRUE(span.has_value());
    EXPECT_EQ(span->from, from);
    EXPECT_EQ(span->to, to);
}

TEST(SlicePlane, KeepsThePlaneAndTheSideAwayFromItsNormal) {
    EXPECT_TRUE(kPlaneX.keeps(Point(0.5, 7.0, -3.0)));
    EXPECT_TRUE(kPlaneX.keeps(Point(0.4, 0.0, 0.0)));
    EXPECT_FALSE(kPlaneX.keeps(Point(0.6, 0.0, 0.0)));
    EXPECT_DOUBLE_EQ(kPlaneX.signedDistance(Point(2.0, 1.0, 1.0)), 1.5);
}

TEST(SlicePlane, ASegmentAcrossThePlaneIsCutAtTheCrossing) {
    const Point a(-1.5, 2.0, 0.0);
    const Point b(2.5, -2.0, 4.0);
    // x = -1.5 + 4 t reaches 0.5 at t = 0.5.
    expectSpan(render::keptSpan(kPlaneX, a, b), 0.0, 0.5);
    expectSpan(render::keptSpan(kPlaneX, b, a), 0.5, 1.0);
    EXPECT_EQ(render::pointAlong(a, b, 0.5), Point(0.5, 0.0, 2.0));
}

TEST(SlicePlane, ASegmentOnTheKeptSideIsKeptWhole) {
    expectSpan(render::keptSpan(kPlaneX, Point(-3.0, 1.0, 1.0), Point(0.0, 9.0, -2.0)), 0.0, 1.0);
    // Ending on the plane is still the whole segment.
    expectSpan(render::keptSpan(kPlaneX, Point(-3.0, 1.0, 1.0), Point(0.5, 9.0, -2.0)), 0.0, 1.0);
}

TEST(SlicePlane, ASegmentOnTheHiddenSideIsDropped) {
    EXPECT_FALSE(render::keptSpan(kPlaneX, Point(0.7, 1.0, 1.0), Point(4.0, -1.0, 0.0)));
    // Touching the plane at one end keeps a point, which draws nothing: dropped too.
    EXPECT_FALSE(render::keptSpan(kPlaneX, Point(0.5, 1.0, 1.0), Point(4.0, -1.0, 0.0)));
    EXPECT_FALSE(render::keptSpan(kPlaneX, Point(4.0, -1.0, 0.0), Point(0.5, 1.0, 1.0)));
}

TEST(SlicePlane, ASegmentInThePlaneIsKeptWhole) {
    expectSpan(render::keptSpan(kPlaneX, Point(0.5, -1.0, 3.0), Point(0.5, 2.0, -3.0)), 0.0, 1.0);
}

TEST(SlicePlane, AnInvalidNormalHidesNothing) {
    const SlicePlane none{Point::Zero(), Direction(0.0, 0.0, 0.0)};
    EXPECT_TRUE(none.keeps(Point(1.0, 2.0, 3.0)));
    expectSpan(render::keptSpan(none, Point(-1.0, 0.0, 0.0), Point(1.0, 0.0, 0.0)), 0.0, 1.0);
}

TEST(SlicePlane, PointAlongIsExactAtBothEnds) {
    const Point a(0.1, 1e8 + 0.3, -7.7);
    const Point b(1e-9, 3.3, 1e5);
    EXPECT_EQ(render::pointAlong(a, b, 0.0), a);
    EXPECT_EQ(render::pointAlong(a, b, 1.0), b);
}

// Random planes and segments across them, far from the origin too: the cut end lies on the plane to
// rounding (a few ulps of the coordinates), the other end is the kept one, and the kept part is on the
// kept side. The failing case's index is printed to replay it.
TEST(SlicePlane, CutEndsLieOnThePlaneForRandomSegments) {
    for (int index = 0; index < 2000; ++index) {
        std::mt19937_64 random(static_cast<std::uint64_t>(index));
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        const double scale = std::pow(10.0, 6.0 * (unit(random) + 1.0) - 3.0);  // 1e-3 to 1e9
        const auto point = [&]() -> Point {
            const double x = unit(random);
            const double y = unit(random);
            return {x, y, unit(random)};
        };
        const Point offset = scale * point();
        const SlicePlane plane{offset + 0.3 * point(), Direction(point())};
        const Point a = offset + point();
        const Point b = offset + point();
        const std::optional<SegmentSpan> span = render::keptSpan(plane, a, b);
        const bool keepA = plane.keeps(a);
        const bool keepB = plane.keeps(b);
        if (keepA && keepB) {
            ASSERT_TRUE(span) << "case " << index;
            EXPECT_EQ(span->from, 0.0) << "case " << index;
            EXPECT_EQ(span->to, 1.0) << "case " << index;
            continue;
        }
        if (!keepA && !keepB) {
            EXPECT_FALSE(span) << "case " << index;
            continue;
        }
        ASSERT_TRUE(span) << "case " << index;
        const double cut = keepA ? span->to : span->from;
        const Point onPlane = render::pointAlong(a, b, cut);
        const double rounding = 16.0 * std::numeric_limits<double>::epsilon() * (onPlane.norm() + (b - a).norm());
        EXPECT_LE(std::abs(plane.signedDistance(onPlane)), rounding) << "case " << index;
        EXPECT_EQ(keepA ? span->from : span->to, keepA ? 0.0 : 1.0) << "case " << index;
        EXPECT_TRUE(plane.keeps(render::pointAlong(a, b, 0.5 * (span->from + span->to)))) << "case " << index;
    }
}

TEST(SliceLines, ACutSegmentEndsOnThePlaneWithItsColourInterpolated) {
    const render::Anchor anchor{Point(10.0, 20.0, 30.0)};
    LineBatch lines(anchor);
    const Colour black{0.0f, 0.0f, 0.0f, 1.0f};
    const Colour white{1.0f, 1.0f, 1.0f, 1.0f};
    lines.add(Point(-1.5, 0.0, 0.0), Point(2.5, 0.0, 0.0), black, white);  // cut at 1/2
    lines.add(Point(1.0, 1.0, 0.0), Point(3.0, 1.0, 0.0), white);          // hidden
    lines.add(Point(0.0, 2.0, 0.0), Point(-2.0, 2.0, 0.0), white, black);  // kept

    LineBatch cut(anchor);
    render::appendKeptSegments(cut, lines, kPlaneX, anchor);
    const auto& vertices = cut.vertices();
    ASSERT_EQ(vertices.size(), 4u);
    EXPECT_EQ(positionOf(vertices[0], anchor), Point(-1.5, 0.0, 0.0));
    EXPECT_EQ(positionOf(vertices[1], anchor), Point(0.5, 0.0, 0.0));
    expectColour(vertices[0].colour, black);
    expectColour(vertices[1].colour, {0.5f, 0.5f, 0.5f, 1.0f});
    EXPECT_EQ(positionOf(vertices[2], anchor), Point(0.0, 2.0, 0.0));
    EXPECT_EQ(positionOf(vertices[3], anchor), Point(-2.0, 2.0, 0.0));
    expectColour(vertices[2].colour, white);
    expectColour(vertices[3].colour, black);
}

// Every segment of `lines` is kept by a plane beyond them all, and comes out bit for bit as it went in.
void expectUnchangedByAPlaneBeyond(const LineBatch& lines, const render::Anchor& anchor, const Point& beyond) {
    LineBatch cut(anchor);
    render::appendKeptSegments(cut, lines, {beyond, Direction(0.0, 0.0, 1.0)}, anchor);
    ASSERT_EQ(cut.vertices().size(), lines.vertices().size());
    for (std::size_t k = 0; k < lines.vertices().size(); ++k) {
        ASSERT_EQ(cut.vertices()[k].position, lines.vertices()[k].position) << "vertex " << k;
        ASSERT_EQ(cut.vertices()[k].colour, lines.vertices()[k].colour) << "vertex " << k;
    }
}

// Kept segments go through the anchor and back (appendKeptSegments): the cloud's octree cells with the
// anchor at the centre and far off, and tiny segments next to an anchor far from the origin.
TEST(SliceLines, APlaneBeyondEverythingLeavesTheLinesAsTheyWere) {
    const Scene scene = loadScene(kCloudScene);
    const OpticalScene optical(scene);
    const Eigen::AlignedBox3d bounds = render::sceneBounds(optical.octree().shapes());
    for (const Point& origin : {Point(bounds.center()), Point(1e4, -3e3, 7.25)}) {
        const render::Anchor anchor{origin};
        LineBatch lines(anchor);
        render::addOctreeCells(lines, optical.octree(), {render::OctreeFilter::Mode::All, 0, false});
        expectUnchangedByAPlaneBeyond(lines, anchor, Point(0.0, 0.0, 1e3));
    }

    const render::Anchor far{Point(1e8, -1e8, 3e7)};
    LineBatch tiny(far);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> offset(-1e-3, 1e-3);
    const auto near = [&]() -> Point {
        const double x = offset(random);
        const double y = offset(random);
        return far.origin + Point(x, y, offset(random));
    };
    for (int k = 0; k < 10000; ++k) tiny.add(near(), near(), {0.3f, 0.6f, 0.9f, 1.0f});
    expectUnchangedByAPlaneBeyond(tiny, far, far.origin + Point(0.0, 0.0, 1.0));
}

// The default scene: drop-a (centre z = 0), drop-b (-1), drop-c (-1.2), the glass cell (4) and the drop
// in it (4). The plane z = 0 hiding +z keeps the first three, drop-a by being on the plane.
TEST(SliceShapes, ShapesAreKeptOrHiddenByTheirCenter) {
    const Scene scene = loadScene(kDefaultScene);
    const render::Anchor anchor{Point(0.0, 0.0, 1.0)};
    const render::ShapeInstances all = render::buildShapeInstances(scene.shapes, anchor);
    const SlicePlane plane{Point::Zero(), Direction(0.0, 0.0, 1.0)};
    const render::ShapeInstances kept = render::keptShapes(all, scene.shapes, plane);
    EXPECT_EQ(kept.roundedIds, (std::vector<ShapeId>{0, 1, 2}));
    EXPECT_TRUE(kept.boxIds.empty());
    ASSERT_EQ(kept.rounded.size(), 3u);
    EXPECT_TRUE(kept.boxes.empty());
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(kept.rounded[k].center, all.rounded[k].center);

    const render::ShapeInstances flipped =
        render::keptShapes(all, scene.shapes, {Point::Zero(), Direction(0.0, 0.0, -1.0)});
    EXPECT_EQ(flipped.roundedIds, (std::vector<ShapeId>{0, 4}));
    EXPECT_EQ(flipped.boxIds, (std::vector<ShapeId>{3}));
}

// Every layer of the default scene at once, sliced through the middle: no line vertex and no marker on
// the hidden side, cut ends on the plane, and the axes and the source glyph whole.
TEST(SliceLayers, LinesAreCutAndMarkersHiddenButTheGuidesStayWhole) {
    const Scene scene = loadScene(kDefaultScene);
    const OpticalScene optical(scene);
    TraceSettings settings;
    settings.photons = 200;
    settings.paths = 200;
    const TraceResult traced = runTrace(optical, scene.sources, settings, TallySet{});
    const Eigen::AlignedBox3d bounds = render::sceneBounds(optical.octree().shapes());
    render::LayerInputs inputs{optical.octree(), scene.sources, bounds};
    inputs.paths = &traced.paths;
    const render::Anchor anchor{bounds.center()};

    render::LayerOptions options;
    options.octree = true;
    options.octreeFilter = {render::OctreeFilter::Mode::All, 0, false};
    options.markers = true;
    options.grid = true;
    const render::SceneLayers whole = render::buildSceneLayers(inputs, options, anchor);
    const SlicePlane plane{Point(0.0, 0.0, 0.3), Direction(0.2, 0.1, 1.0)};
    options.slice = plane;
    const render::SceneLayers sliced = render::buildSceneLayers(inputs, options, anchor);

    ASSERT_LT(sliced.lines.vertices().size(), whole.lines.vertices().size());
    ASSERT_LT(sliced.markers.size(), whole.markers.size());
    ASSERT_FALSE(sliced.markers.empty());
    const double rounding = 1e-5 * bounds.diagonal().norm();  // the float the positions are drawn in
    int onPlane = 0;
    for (const LineVertex& vertex : sliced.lines.vertices()) {
        const double distance = plane.signedDistance(positionOf(vertex, anchor));
        EXPECT_LE(distance, rounding);
        onPlane += std::abs(distance) <= rounding ? 1 : 0;
    }
    EXPECT_GT(onPlane, 0) << "no segment was cut";
    for (const render::ShapeInstance& marker : sliced.markers) {
        EXPECT_TRUE(plane.keeps(anchor.origin + Point(marker.center[0], marker.center[1], marker.center[2])));
    }

    // The guides: with only the axes and the sources on, the slice changes nothing.
    render::LayerOptions guides;
    guides.paths = false;
    guides.axes = true;
    guides.sources = true;
    const render::SceneLayers unsliced = render::buildSceneLayers(inputs, guides, anchor);
    guides.slice = SlicePlane{bounds.center(), Direction(0.0, 0.0, -1.0)};
    const render::SceneLayers guidesSliced = render::buildSceneLayers(inputs, guides, anchor);
    ASSERT_EQ(guidesSliced.lines.vertices().size(), unsliced.lines.vertices().size());
    for (std::size_t k = 0; k < unsliced.lines.vertices().size(); ++k) {
        EXPECT_EQ(guidesSliced.lines.vertices()[k].position, unsliced.lines.vertices()[k].position);
    }
}

// Two spheres either side of the plane x = 0, seen from +z: without the slice both are drawn, with it
// only the one at x < 0, whose centre is on the kept side. The pixels at the projected centres say so.
TEST(SliceRender, OnlyTheSphereOnTheKeptSideIsDrawn) {
    const Scene scene = parseScene(
        R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "water": {"n": 1.333}},
            "shapes": [{"type": "sphere", "center": [-2, 0, 0], "radius": 1, "medium": "water"},
                       {"type": "sphere", "center": [2, 0, 0], "radius": 1, "medium": "water"}]})",
        "two_spheres.json");
    snapshot::SnapshotOptions options;
    options.width = 160;
    options.height = 120;
    options.eye = Point(0.0, 0.0, 12.0);
    options.target = Point::Zero();
    options.layers.render.background = {0.0f, 0.0f, 0.0f, 1.0f};
    const render::Camera camera =
        test::cameraLookingAt(*options.eye, *options.target, 40.0, render::sceneBounds(scene.shapes));
    const auto pixelOf = [&](const Point& center) {
        const Eigen::Vector2d p = test::projectToPixels(camera, center, options.width, options.height);
        return std::pair{static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y()))};
    };
    const auto [leftX, leftY] = pixelOf(Point(-2.0, 0.0, 0.0));
    const auto [rightX, rightY] = pixelOf(Point(2.0, 0.0, 0.0));
    ASSERT_LT(leftX, options.width / 2);
    ASSERT_GT(rightX, options.width / 2);

    const snapshot::Image both = snapshot::renderSnapshot(scene, options);
    EXPECT_FALSE(test::isBlack(both, leftX, leftY));
    EXPECT_FALSE(test::isBlack(both, rightX, rightY));

    options.layers.slice = SlicePlane{Point::Zero(), Direction(1.0, 0.0, 0.0)};
    const snapshot::Image sliced = snapshot::renderSnapshot(scene, options);
    EXPECT_FALSE(test::isBlack(sliced, leftX, leftY)) << "the kept sphere is not drawn";
    EXPECT_TRUE(test::isBlack(sliced, rightX, rightY)) << "the hidden sphere is drawn";
    EXPECT_TRUE(test::samePixel(sliced, leftX, leftY, both.pixel(leftX, leftY))) << "the kept sphere changed";
}

}  // namespace
}  // namespace dropscope
