// Chords (render/Chords.hpp): which path and ray-tree segments lie inside a sphere or ellipsoid, and the
// renderer leaving them out only where its picture is the same without them.
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "render/Layers.hpp"
#include "render/RenderHarness.hpp"
#include "scene/SceneLoader.hpp"
#include "transport/OpticalScene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dropscope {
namespace {

using render::LineBatch;

const std::string kDefaultScene = std::string(DROPSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";

Event at(EventType type, const Point& position, ShapeId shape = RayHit::kNone) {
    Event event{type, position, Direction(1, 0, 0)};
    event.shape = shape;
    return event;
}

Point worldOf(const render::LineVertex& vertex) {
    return Point(vertex.position[0], vertex.position[1], vertex.position[2]);
}

// The segments of a batch as pairs of points (the anchor at the origin).
std::vector<std::pair<Point, Point>> segmentsOf(const LineBatch& batch) {
    std::vector<std::pair<Point, Point>> segments;
    for (std::size_t k = 0; k + 1 < batch.vertices().size(); k += 2)
        segments.emplace_back(worldOf(batch.vertices()[k]), worldOf(batch.vertices()[k + 1]));
    return segments;
}

// A sphere (0), an ellipsoid (1) and a box (2) along the x axis, `shift` moving the sphere.
Octree threeShapes(const Point& shift = Point::Zero()) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(shift, 1.0));
    shapes.push_back(
        std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(Point(4, 0, 0), Eigen::Vector3d(1, 0.5, 0.5))));
    shapes.push_back(std::make_unique<Box>(Point(7, -1, -1), Point(9, 1, 1)));
    return Octree(std::move(shapes));
}

// In at the sphere's left, reflected inside at its top, out at its right; through the ellipsoid and the
// box; absorbed in a second pass through the sphere.
PhotonPath pathThroughThreeShapes() {
    PhotonPath path;
    path.events = {at(EventType::Emit, Point(-5, 0, 0)),      at(EventType::Refract, Point(-1, 0, 0), 0),
                   at(EventType::Reflect, Point(0, 1, 0), 0), at(EventType::Refract, Point(1, 0, 0), 0),
                   at(EventType::Refract, Point(3, 0, 0), 1), at(EventType::Refract, Point(5, 0, 0), 1),
                   at(EventType::Refract, Point(7, 0, 0), 2), at(EventType::Refract, Point(9, 0, 0), 2),
                   at(EventType::Refract, Point(0, 0, 1), 0), at(EventType::Absorb, Point(0, 0, 0.5)),
                   at(EventType::Lost, Point(0, 0, 0.5))};
    return path;
}

TEST(Chords, ThePathsSegmentsInsideASphereOrEllipsoidGoToTheChords) {
    const Octree octree = threeShapes();
    LineBatch lines{render::Anchor{}};
    LineBatch chords{render::Anchor{}};
    const render::ChordSplit split{octree, chords};
    render::addPhotonPaths(lines, {pathThroughThreeShapes()}, 1.0, render::PathColouring::Weight, &split);

    const std::vector<std::pair<Point, Point>> expectedChords{
        {Point(-1, 0, 0), Point(0, 1, 0)}, {Point(0, 1, 0), Point(1, 0, 0)}, {Point(3, 0, 0), Point(5, 0, 0)}};
    EXPECT_EQ(segmentsOf(chords), expectedChords);
    // The rest: to and from each shape, across the box (not rounded), and the entry to an absorption and
    // the absorption to the loss (not interface events at one shape).
    const std::vector<std::pair<Point, Point>> expectedLines{
        {Point(-5, 0, 0), Point(-1, 0, 0)},  {Point(1, 0, 0), Point(3, 0, 0)}, {Point(5, 0, 0), Point(7, 0, 0)},
        {Point(7, 0, 0), Point(9, 0, 0)},    {Point(9, 0, 0), Point(0, 0, 1)}, {Point(0, 0, 1), Point(0, 0, 0.5)},
        {Point(0, 0, 0.5), Point(0, 0, 0.5)}};
    EXPECT_EQ(segmentsOf(lines), expectedLines);
}

TEST(Chords, ASphereMovedOffThePathSinceTheTraceNoLongerHidesIt) {
    const Octree moved = threeShapes(Point(0.5, 0, 0));
    const PhotonPath path = pathThroughThreeShapes();
    EXPECT_FALSE(render::isChord(path.events[1], path.events[2], moved));
    EXPECT_FALSE(render::isChord(path.events[2], path.events[3], moved));
    EXPECT_TRUE(render::isChord(path.events[4], path.events[5], moved));  // the ellipsoid stayed
    const Octree inPlace = threeShapes();
    EXPECT_TRUE(render::isChord(path.events[1], path.events[2], inPlace));
}

// With a slice plane nothing is split off: the slice leaves droplets out by their centre but cuts the lines at
// the plane, so a chord may outlive its droplet.
TEST(Chords, WithASlicePlaneNoneAreSplitOff) {
    const Octree octree = threeShapes();
    const std::vector<Source> sources;
    const std::vector<PhotonPath> paths{pathThroughThreeShapes()};
    render::LayerInputs inputs{octree, sources, render::sceneBounds(octree.shapes())};
    inputs.paths = &paths;
    render::LayerOptions options;
    const render::SceneLayers whole = render::buildSceneLayers(inputs, options, render::Anchor{});
    EXPECT_EQ(whole.chords.vertices().size(), 6u);
    options.slice = render::SlicePlane{Point(0, 0, 10), Direction(0, 0, 1)};  // keeps everything
    const render::SceneLayers sliced = render::buildSceneLayers(inputs, options, render::Anchor{});
    EXPECT_TRUE(sliced.chords.empty());
    EXPECT_EQ(sliced.lines.vertices().size(), whole.lines.vertices().size() + whole.chords.vertices().size());
}

// A trace's compact ids (the document's empty slots left out) name the shapes through its map of slots.
TEST(Chords, TheEventsShapeIdsGoThroughTheTracesSlots) {
    const Octree octree = threeShapes();
    PhotonPath path = pathThroughThreeShapes();
    for (Event& event : path.events) {
        if (event.shape != RayHit::kNone) event.shape = event.shape == 0 ? 1 : (event.shape == 1 ? 0 : 2);
    }
    const std::vector<ShapeId> slots{1, 0, 2};                              // compact 1 is the sphere's slot 0
    EXPECT_FALSE(render::isChord(path.events[1], path.events[2], octree));  // the ellipsoid does not hold them
    EXPECT_TRUE(render::isChord(path.events[1], path.events[2], octree, &slots));
    EXPECT_TRUE(render::isChord(path.events[4], path.events[5], octree, &slots));
    const std::vector<ShapeId> short_{1};
    EXPECT_FALSE(render::isChord(path.events[1], path.events[2], octree, &short_));  // compact 1 has no slot
}

// The ray tree's segments are split without losing or reordering any: the lines and the chords are the
// unsplit batch's segments, each in the order it had there.
TEST(Chords, TheRayTreesChordsAreItsSegmentsInsideItsDroplets) {
    Scene scene = loadScene(kDefaultScene);
    const OpticalScene optical(scene);
    const RayTree tree = traceRayTree(optical, Ray{Point(0.3, 0.2, -8.0), Direction(0, 0, 1)}, 1.0, RayTreeSettings{});
    LineBatch all{render::Anchor{}};
    render::addRayTree(all, tree, 1.0);
    LineBatch lines{render::Anchor{}};
    LineBatch chords{render::Anchor{}};
    const render::ChordSplit split{optical.octree(), chords};
    render::addRayTree(lines, tree, 1.0, &split);

    const auto chordSegments = segmentsOf(chords);
    const auto lineSegments = segmentsOf(lines);
    ASSERT_GT(chordSegments.size(), 3u);
    ASSERT_GT(lineSegments.size(), 3u);
    std::size_t line = 0;
    std::size_t chord = 0;
    for (const auto& [from, to] : segmentsOf(all)) {
        const bool inChords = chord < chordSegments.size() && chordSegments[chord] == std::make_pair(from, to);
        if (inChords) {
            ++chord;
            // Both ends in one droplet: its centre nearer than its radius (a little more: float vertices).
            bool inside = false;
            for (const auto& shape : optical.octree().shapes()) {
                const auto* sphere = dynamic_cast<const Sphere*>(shape.get());
                inside = inside || (sphere && (from - sphere->center()).norm() < sphere->radius() * (1 + 1e-6) &&
                                    (to - sphere->center()).norm() < sphere->radius() * (1 + 1e-6));
            }
            EXPECT_TRUE(inside) << from.transpose() << " -> " << to.transpose();
        } else {
            ASSERT_LT(line, lineSegments.size());
            EXPECT_EQ(lineSegments[line], std::make_pair(from, to));
            ++line;
        }
    }
    EXPECT_EQ(chord, chordSegments.size());
    EXPECT_EQ(line, lineSegments.size());
}

// A ray tree's draw order worked out beforehand, against a copy of the shapes with ids of its own (a trace's
// compact scene), gives the batches the layer works out itself against the document's octree through the slots;
// one given is taken as it is; one of another tree (another count of segments) is not taken.
TEST(Chords, ARayTreesDrawOrderWorkedOutBeforehandGivesTheSameLines) {
    Scene scene = loadScene(kDefaultScene);
    const OpticalScene optical(scene);
    const RayTree tree = traceRayTree(optical, Ray{Point(0.3, 0.2, -8.0), Direction(0, 0, 1)}, 1.0, RayTreeSettings{});
    // The document: the same shapes after another one in slot 0, so that slot k + 1 holds the tree's shape k.
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(100, 100, 100), 0.1));
    std::vector<ShapeId> slots;
    for (const auto& shape : optical.octree().shapes()) {
        shapes.push_back(shape->clone());
        slots.push_back(static_cast<ShapeId>(slots.size() + 1));
    }
    const Octree document(std::move(shapes));

    const auto batches = [&](const render::RayTreeDrawOrder* prepared) {
        std::pair<LineBatch, LineBatch> made{LineBatch{render::Anchor{}}, LineBatch{render::Anchor{}}};
        const render::ChordSplit split{document, made.second, &slots};
        render::addRayTree(made.first, tree, 1.0, &split, prepared);
        return std::pair{segmentsOf(made.first), segmentsOf(made.second)};
    };
    const auto workedOut = batches(nullptr);
    ASSERT_GT(workedOut.second.size(), 3u);
    const render::RayTreeDrawOrder beforehand = render::rayTreeDrawOrder(tree, &optical.octree());
    EXPECT_EQ(batches(&beforehand), workedOut);

    render::RayTreeDrawOrder reversed = beforehand;
    std::reverse(reversed.order.begin(), reversed.order.end());
    reversed.chord.flip();
    auto [lines, chords] = batches(&reversed);
    std::reverse(lines.begin(), lines.end());
    std::reverse(chords.begin(), chords.end());
    EXPECT_EQ(lines, workedOut.second);
    EXPECT_EQ(chords, workedOut.first);

    // Without chords (a slice plane) the order is taken and its chords are not.
    LineBatch unsplit{render::Anchor{}};
    render::addRayTree(unsplit, tree, 1.0, nullptr, &reversed);
    std::vector<std::pair<Point, Point>> drawn = segmentsOf(unsplit);
    std::reverse(drawn.begin(), drawn.end());
    LineBatch all{render::Anchor{}};
    render::addRayTree(all, tree, 1.0);
    EXPECT_EQ(drawn, segmentsOf(all));

    const RayTree another =
        traceRayTree(optical, Ray{Point(-0.2, 0.1, -8.0), Direction(0, 0, 1)}, 1.0, RayTreeSettings{});
    const render::RayTreeDrawOrder ofAnotherTree = render::rayTreeDrawOrder(another, &optical.octree());
    ASSERT_NE(ofAnotherTree.order.size(), beforehand.order.size());
    EXPECT_EQ(batches(&ofAnotherTree), workedOut);
}

// The renderer, through a GL table whose DrawArrays records the vertex counts of the lines it draws.
std::vector<GLsizei>& lineDraws() {
    static std::vector<GLsizei> draws;
    return draws;
}
PFNGLDRAWARRAYSPROC& realDrawArrays() {
    static PFNGLDRAWARRAYSPROC real = nullptr;
    return real;
}
void APIENTRY recordingDrawArrays(GLenum mode, GLint first, GLsizei count) {
    if (mode == GL_LINES) lineDraws().push_back(count);
    realDrawArrays()(mode, first, count);
}

class ChordsDrawn : public ::testing::Test {
protected:
    static constexpr int kWidth = 160;
    static constexpr int kHeight = 120;
    inline static const Eigen::AlignedBox3d kBounds{Point(-4, -4, -4), Point(4, 4, 6)};  // the camera's planes

    ChordsDrawn() : context_(kWidth, kHeight), gl_(recording(context_.gl())), renderer_(gl_) {
        std::vector<std::unique_ptr<Shape>> shapes;
        shapes.push_back(std::make_unique<Sphere>(Point::Zero(), 1.0));
        octree_ = std::make_unique<Octree>(std::move(shapes));
        // From in front of the sphere (+z) to its front, across to its back, reflected there to its lower
        // left and out: two chords, the second (from the reflection) orange, the only orange segment.
        const double s = std::sqrt(0.5);
        PhotonPath path;
        path.events = {at(EventType::Emit, Point(0.3, 0.2, 5.0)),
                       at(EventType::Refract, Point(0.3, 0.2, std::sqrt(0.87)), 0),
                       at(EventType::Reflect, Point(0.0, 0.6, -0.8), 0), at(EventType::Refract, Point(-s, -s, 0.0), 0),
                       at(EventType::Escape, Point(-3.0, -3.0, 0.0))};
        paths_ = {path};
    }

    static render::GlFunctions recording(const render::GlFunctions& real) {
        realDrawArrays() = real.DrawArrays;
        render::GlFunctions table = real;
        table.DrawArrays = &recordingDrawArrays;
        return table;
    }

    // The layers uploaded as the app does (the chords kept apart), then one frame from `eye`.
    // `nearPlane`, when given, in place of the one fitted to the bounds.
    snapshot::Image draw(const Point& eye, render::RenderOptions options, std::optional<double> nearPlane = {}) {
        render::LayerOptions layerOptions;
        layerOptions.pathColouring = render::PathColouring::Event;
        render::LayerInputs inputs{*octree_, sources_, render::sceneBounds(octree_->shapes())};
        inputs.paths = &paths_;
        const render::Anchor anchor{};
        renderer_.setAnchor(anchor);
        layers_ = std::make_unique<render::SceneLayers>(render::buildSceneLayers(inputs, layerOptions, anchor));
        render::uploadScene(renderer_, octree_->shapes(), *layers_, layerOptions);
        render::Camera camera = test::cameraLookingAt(eye, Point(0, 0, -1), 60.0, kBounds);
        if (nearPlane) camera.nearPlane = *nearPlane;
        options.background = {0.0f, 0.0f, 0.0f, 1.0f};
        lineDraws().clear();
        renderer_.draw(camera, options, kWidth, kHeight);
        return context_.read();
    }

    GLsizei drawnLineVertices() const {
        GLsizei total = 0;
        for (const GLsizei count : lineDraws()) total += count;
        return total;
    }
    GLsizei chordVertices() const { return static_cast<GLsizei>(layers_->chords.vertices().size()); }
    GLsizei otherLineVertices() const { return static_cast<GLsizei>(layers_->lines.vertices().size()); }

    static int orangePixels(const snapshot::Image& image) {
        const render::Colour orange = render::eventColour(EventType::Reflect);
        int count = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                bool same = true;
                for (int c = 0; c < 3; ++c) same = same && std::abs(p[c] - std::lround(255.0f * orange[c])) <= 1;
                count += same ? 1 : 0;
            }
        }
        return count;
    }

    snapshot::OsmesaContext context_;
    render::GlFunctions gl_;
    render::Renderer renderer_;
    std::unique_ptr<Octree> octree_;
    std::vector<Source> sources_;
    std::vector<PhotonPath> paths_;
    std::unique_ptr<render::SceneLayers> layers_;
};

// Seen from outside, the opaque sphere hides both chords: the frame leaves them out and its picture is the
// one drawn with them, pixel for pixel.
TEST_F(ChordsDrawn, HiddenBehindTheOpaqueSphereTheyAreLeftOutAndThePictureIsTheSame) {
    const Point eye(0.5, 0.8, 6.0);
    render::RenderOptions withChords;
    withChords.skipHiddenChords = false;
    const snapshot::Image all = draw(eye, withChords);
    ASSERT_EQ(chordVertices(), 4);
    EXPECT_EQ(drawnLineVertices(), otherLineVertices() + chordVertices());
    const snapshot::Image skipping = draw(eye, render::RenderOptions{});
    EXPECT_EQ(drawnLineVertices(), otherLineVertices());
    EXPECT_EQ(orangePixels(all), 0);
    // Pixel for pixel the same, but for where a chord starts on the face towards the eye: there it ties in
    // depth with the surface, and drawn, its first pixel may win.
    const render::Camera camera = test::cameraLookingAt(eye, Point(0, 0, -1), 60.0, kBounds);
    const Eigen::Vector2d entry = test::projectToPixels(camera, paths_[0].events[1].position, kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (test::samePixel(all, x, y, skipping.pixel(x, y))) continue;
            EXPECT_LT((Eigen::Vector2d(x + 0.5, y + 0.5) - entry).lpNorm<Eigen::Infinity>(), 1.0)
                << "differs at " << x << ", " << y;
        }
    }
}

// Where the sphere cannot hide them they are drawn: the eye inside it, the shapes blended, or not drawn.
TEST_F(ChordsDrawn, DrawnWhereTheyCanShow) {
    render::RenderOptions translucent;
    translucent.translucent = true;
    render::RenderOptions noShapes;
    noShapes.shapes = false;
    const std::pair<Point, render::RenderOptions> cases[] = {{Point(0.1, 0.1, 0.6), render::RenderOptions{}},
                                                             {Point(0.5, 0.8, 6.0), translucent},
                                                             {Point(0.5, 0.8, 6.0), noShapes}};
    for (const auto& [eye, options] : cases) {
        const snapshot::Image image = draw(eye, options);
        EXPECT_EQ(drawnLineVertices(), otherLineVertices() + chordVertices()) << eye.transpose();
        if (!options.translucent) {
            EXPECT_GT(orangePixels(image), 10) << eye.transpose();
        }
    }
}

// The eye outside the sphere, 3 from its front: a near plane 3.2 ahead cuts it open and the chords are drawn.
// The test is against the chunk's bounding sphere, around the box of its shapes' bounds (here sqrt(3) times
// the sphere's radius, 2.27 from the eye), so a near plane 1.5 ahead, short of it even at its corners
// (1.01 x 1.5 / cos of their angle off the axis: 2.1 at this field of view and aspect), leaves them out.
TEST_F(ChordsDrawn, DrawnWhenTheNearPlaneCutsTheSphereOpen) {
    const Point eye(0.0, 0.0, 4.0);
    draw(eye, render::RenderOptions{}, 3.2);
    EXPECT_EQ(drawnLineVertices(), otherLineVertices() + chordVertices());
    draw(eye, render::RenderOptions{}, 1.5);
    EXPECT_EQ(drawnLineVertices(), otherLineVertices());
}

}  // namespace
}  // namespace dropscope
