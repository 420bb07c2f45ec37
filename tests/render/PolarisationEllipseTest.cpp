// The polarisation ellipse (render/PolarisationEllipse.hpp) as line segments, no GL: where its vertices
// lie for linear, circular and elliptical light in random frames, the grey circle across the direction (all
// that is drawn of unpolarised light), and its place first in the scene's line batch.
#include "geometry/Sphere.hpp"
#include "render/Layers.hpp"
#include "transport/Emission.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace dropscope {
namespace {

using render::LineBatch;
using render::LineVertex;

constexpr double kSize = 0.75;
// Vertices are floats relative to the anchor (the origin here), about kSize from it.
constexpr double kFloatRounding = 1e-6;
constexpr int kRandomFrames = 50;

Point worldOf(const LineVertex& vertex) { return {vertex.position[0], vertex.position[1], vertex.position[2]}; }

bool sameColour(const render::Colour& a, const render::Colour& b) { return a == b; }

// A light's frame: a random direction k, a random reference perpendicular to it, and a point to draw at.
struct Frame {
    Point at;
    Direction k;
    Eigen::Vector3d parallel;
    Eigen::Vector3d perpendicular;  // parallel x k
};

Frame randomFrame(int seed) {
    std::mt19937_64 random(static_cast<std::uint64_t>(seed));
    std::normal_distribution<double> normal;
    const auto vector = [&] { return Eigen::Vector3d(normal(random), normal(random), normal(random)); };
    Frame frame;
    frame.at = 0.5 * vector();
    frame.k = Direction(vector());
    const Eigen::Vector3d r = vector();
    frame.parallel = (r - r.dot(frame.k.vector()) * frame.k.vector()).normalized();
    frame.perpendicular = frame.parallel.cross(frame.k.vector());
    return frame;
}

// What addPolarisationEllipse drew, as offsets from the frame's point: the ellipse (white), its line along
// the direction and the circle across it (grey), each checked to be where it belongs.
struct Drawn {
    std::vector<Eigen::Vector3d> ellipse;
    render::Colour lineColour{};
};

Drawn drawEllipse(const Frame& frame, const StokesVector& stokes) {
    LineBatch lines{render::Anchor{}};
    render::addPolarisationEllipse(lines, frame.at, frame.k, Polarisation{stokes, frame.parallel}, kSize);
    const auto& vertices = lines.vertices();
    Drawn drawn;
    std::size_t white = 0;
    while (white < vertices.size() && sameColour(vertices[white].colour, render::kEllipseColour)) ++white;
    // The ellipse, then the line from the point along k (the last two white vertices, or the first two).
    const std::size_t line = white > 0 ? white - 2 : 0;
    EXPECT_LT(line + 2, vertices.size());
    if (line + 2 >= vertices.size()) return drawn;
    for (std::size_t v = 0; v < line; ++v) drawn.ellipse.push_back(worldOf(vertices[v]) - frame.at);
    drawn.lineColour = vertices[line].colour;
    EXPECT_LT((worldOf(vertices[line]) - frame.at).norm(), kFloatRounding);
    EXPECT_LT((worldOf(vertices[line + 1]) - (frame.at + kSize * frame.k.vector())).norm(), kFloatRounding);
    // Then the grey circle of radius kSize across k.
    EXPECT_GT(vertices.size(), line + 2 + 3);
    for (std::size_t v = line + 2; v < vertices.size(); ++v) {
        EXPECT_TRUE(sameColour(vertices[v].colour, render::kUnpolarisedColour));
        const Eigen::Vector3d offset = worldOf(vertices[v]) - frame.at;
        EXPECT_NEAR(offset.norm(), kSize, kFloatRounding);
        EXPECT_LT(std::abs(offset.dot(frame.k.vector())), kFloatRounding);
    }
    return drawn;
}

std::vector<Eigen::Vector3d> ellipseOffsets(const Frame& frame, const StokesVector& stokes) {
    const Drawn drawn = drawEllipse(frame, stokes);
    EXPECT_FALSE(drawn.ellipse.empty());
    EXPECT_TRUE(sameColour(drawn.lineColour, render::kEllipseColour));
    return drawn.ellipse;
}

// Every offset lies on the line through the point along `axis` within kSize, and both ends are reached.
void expectSegmentAlong(const std::vector<Eigen::Vector3d>& offsets, const Eigen::Vector3d& axis) {
    double lowest = 0.0;
    double highest = 0.0;
    for (const Eigen::Vector3d& offset : offsets) {
        const double along = offset.dot(axis);
        EXPECT_LT((offset - along * axis).norm(), kFloatRounding) << "off the axis";
        EXPECT_LE(std::abs(along), kSize + kFloatRounding);
        lowest = std::min(lowest, along);
        highest = std::max(highest, along);
    }
    EXPECT_NEAR(lowest, -kSize, kFloatRounding);
    EXPECT_NEAR(highest, kSize, kFloatRounding);
}

TEST(PolarisationEllipse, LiesInThePlanePerpendicularToTheDirection) {
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal;
    for (int seed = 0; seed < kRandomFrames; ++seed) {
        const Frame frame = randomFrame(seed);
        // A random state 90 % polarised: (Q, U, V) / I on the sphere of radius 0.9.
        const Eigen::Vector3d state = Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
        const StokesVector stokes(1.0, 0.9 * state.x(), 0.9 * state.y(), 0.9 * state.z());
        const auto offsets = ellipseOffsets(frame, stokes);
        ASSERT_FALSE(offsets.empty());
        for (const Eigen::Vector3d& offset : offsets) {
            EXPECT_LT(std::abs(offset.dot(frame.k.vector())), kFloatRounding) << "frame " << seed;
            EXPECT_LE(offset.norm(), kSize + kFloatRounding) << "frame " << seed;
        }
    }
}

TEST(PolarisationEllipse, LinearLightIsASegmentAtPsiFromTheReference) {
    for (int seed = 0; seed < kRandomFrames; ++seed) {
        const Frame frame = randomFrame(seed);
        // Q = I: along the reference; Q = -I: along the perpendicular axis; U = +-I: at +-45 degrees.
        expectSegmentAlong(ellipseOffsets(frame, {1.0, 1.0, 0.0, 0.0}), frame.parallel);
        expectSegmentAlong(ellipseOffsets(frame, {2.0, -2.0, 0.0, 0.0}), frame.perpendicular);
        expectSegmentAlong(ellipseOffsets(frame, {1.0, 0.0, 1.0, 0.0}),
                           (frame.parallel + frame.perpendicular).normalized());
        expectSegmentAlong(ellipseOffsets(frame, {1.0, 0.0, -1.0, 0.0}),
                           (frame.parallel - frame.perpendicular).normalized());
        // Linear at A from the reference towards the perpendicular axis: Q = I cos 2A, U = I sin 2A.
        const double a = (seed - kRandomFrames / 2) * std::numbers::pi / kRandomFrames;
        expectSegmentAlong(ellipseOffsets(frame, {1.0, std::cos(2.0 * a), std::sin(2.0 * a), 0.0}),
                           std::cos(a) * frame.parallel + std::sin(a) * frame.perpendicular);
    }
}

TEST(PolarisationEllipse, PartlyPolarisedLinearLightIsTheSameSegment) {
    const Frame frame = randomFrame(3);
    expectSegmentAlong(ellipseOffsets(frame, {1.0, 0.3, 0.0, 0.0}), frame.parallel);
}

TEST(PolarisationEllipse, CircularLightIsACircle) {
    for (const double v : {1.0, -1.0}) {
        const Frame frame = randomFrame(11);
        const auto offsets = ellipseOffsets(frame, {1.0, 0.0, 0.0, v});
        ASSERT_FALSE(offsets.empty());
        for (const Eigen::Vector3d& offset : offsets) EXPECT_NEAR(offset.norm(), kSize, kFloatRounding);
    }
}

TEST(PolarisationEllipse, EllipticalLightHasAxesAtPsiWithRatioTanChi) {
    const double psi = 0.3;
    const double chi = -0.2;
    const StokesVector stokes(1.0, std::cos(2 * chi) * std::cos(2 * psi), std::cos(2 * chi) * std::sin(2 * psi),
                              std::sin(2 * chi));
    const render::EllipseShape shape = render::polarisationEllipse(stokes);
    EXPECT_NEAR(shape.degree, 1.0, 1e-12);
    EXPECT_NEAR(shape.orientation, psi, 1e-12);
    EXPECT_NEAR(shape.ellipticity, chi, 1e-12);
    const Frame frame = randomFrame(5);
    const Eigen::Vector3d major = std::cos(psi) * frame.parallel + std::sin(psi) * frame.perpendicular;
    const Eigen::Vector3d minor = frame.k.vector().cross(major);
    double alongMajor = 0.0;
    double alongMinor = 0.0;
    for (const Eigen::Vector3d& offset : ellipseOffsets(frame, stokes)) {
        alongMajor = std::max(alongMajor, std::abs(offset.dot(major)));
        alongMinor = std::max(alongMinor, std::abs(offset.dot(minor)));
        // On the ellipse (x/a)^2 + (y/b)^2 = 1.
        const double b = kSize * std::tan(-chi);
        EXPECT_NEAR(std::pow(offset.dot(major) / kSize, 2) + std::pow(offset.dot(minor) / b, 2), 1.0, 1e-5);
    }
    EXPECT_NEAR(alongMajor, kSize, kFloatRounding);
    EXPECT_NEAR(alongMinor, kSize * std::tan(-chi), kFloatRounding);
}

TEST(PolarisationEllipse, UnpolarisedLightIsTheGreyCircleAlone) {
    const Frame frame = randomFrame(2);
    for (const StokesVector& stokes : {StokesVector(1.0, 0.0, 0.0, 0.0), StokesVector(1.0, 0.005, -0.005, 0.001)}) {
        const Drawn drawn = drawEllipse(frame, stokes);
        EXPECT_TRUE(drawn.ellipse.empty());
        EXPECT_TRUE(sameColour(drawn.lineColour, render::kUnpolarisedColour));
    }
    EXPECT_EQ(render::polarisationEllipse(StokesVector(1.0, 0.0, 0.0, 0.0)).degree, 0.0);
}

TEST(PolarisationEllipse, TheSceneLayersDrawItFirstAtTheCurrentEventOnlyWhenItIsPolarised) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(0.0, 0.0, 0.0), 1.0));
    const Octree octree(std::move(shapes), OctreeSettings{});
    const std::vector<Source> sources;
    PhotonPath path;
    path.events = {Event{EventType::Emit, Point(0, 0, -5), Direction(0, 0, 1)},
                   Event{EventType::Refract, Point(0, 0, -1), Direction(0, 0, 1)}};
    path.events[1].polarisation = Polarisation{{1.0, 1.0, 0.0, 0.0}, Eigen::Vector3d::UnitX()};
    const std::vector<PhotonPath> paths{path};
    render::LayerInputs inputs{octree, sources, render::sceneBounds(octree.shapes())};
    inputs.paths = &paths;
    const render::LayerOptions options;
    const render::Anchor anchor{};
    const std::size_t pathVertices = render::buildSceneLayers(inputs, options, anchor).lines.vertices().size();

    inputs.currentEvent = &path.events[1];
    const render::SceneLayers layers = render::buildSceneLayers(inputs, options, anchor);
    const auto& vertices = layers.lines.vertices();
    ASSERT_GT(vertices.size(), pathVertices);
    const std::size_t ellipse = vertices.size() - pathVertices;
    const double size = render::kEllipseSize * inputs.bounds.diagonal().norm();
    for (std::size_t v = 0; v < ellipse; ++v) {
        const Eigen::Vector3d offset = worldOf(vertices[v]) - path.events[1].position;
        EXPECT_LE(offset.norm(), size + kFloatRounding);
    }
    // Its direction line lies on the path's segment from the event: drawn first, it wins the depth test.
    std::size_t white = 0;
    while (sameColour(vertices[white].colour, render::kEllipseColour)) ++white;
    EXPECT_NEAR(worldOf(vertices[white - 1]).z(), -1.0 + size, kFloatRounding);

    path.events[1].polarisation.reset();
    inputs.currentEvent = &path.events[1];
    const std::vector<PhotonPath> unpolarised{path};
    inputs.paths = &unpolarised;
    EXPECT_EQ(render::buildSceneLayers(inputs, options, anchor).lines.vertices().size(), pathVertices);
}

}  // namespace
}  // namespace dropscope
