// Parametric and implicit shapes are drawn as their meshes (render/MeshCache.hpp): where the camera math
// and the shape's exact geometry say, hidden by the slice plane by the centre of their bounds, blended
// like the droplets, highlighted when selected, and their geometry made once however often the scene is
// uploaded. The shape is a test-local GeneralShape with an exact mesh (TestOctahedron.hpp).
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"
#include "render/MeshCache.hpp"
#include "render/RenderHarness.hpp"
#include "render/RenderTolerances.hpp"
#include "render/SceneLayers.hpp"
#include "render/SilhouetteCoverage.hpp"
#include "render/TestOctahedron.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace dropscope {
namespace {

using test::coveredPixels;
using test::DirectRenderer;
using test::isBlack;
using test::oneShape;
using test::TestOctahedron;

constexpr int kWidth = 160;  // not square: a wrong aspect ratio shows
constexpr int kHeight = 120;

// Colours read back from 8-bit channels: the rounding of one channel, plus one level for the float
// shading (normalize, dot) of two different shader paths at the same point.
constexpr int kChannelLevels = 2;

// An affine map with a rotation, unequal scalings and a shear (so normals and silhouettes are not those
// of a similarity), placed at r0.
AffineTransform randomPlacement(std::mt19937_64& rng, const Point& r0) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> scale(0.6, 1.4);
    const Eigen::Matrix3d rotation =
        rotationAboutAxis(Direction(unit(rng), unit(rng), unit(rng)), std::numbers::pi * unit(rng));
    Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
    shear(0, 1) = 0.3 * unit(rng);
    const Eigen::Matrix3d m = rotation * shear * Eigen::Vector3d(scale(rng), scale(rng), scale(rng)).asDiagonal();
    return AffineTransform(m, r0);
}

// Seeded random placements of the octahedron (rotation, scaling, shear, place), seen from random
// directions, with the anchor elsewhere: every pixel whose ray meets the shape is covered and every
// other one is background, but for at most kBandMismatchShare of the one-pixel band along the silhouette.
TEST(MeshSilhouette, PlacedMeshesCoverExactlyThePixelsWhoseRaysHitTheShape) {
    DirectRenderer renderer(kWidth, kHeight);
    for (int k = 0; k < 6; ++k) {
        SCOPED_TRACE("case " + std::to_string(k));
        std::mt19937_64 rng(static_cast<std::uint64_t>(100 + k));
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        const Point r0(50.0 * unit(rng), 50.0 * unit(rng), 50.0 * unit(rng));
        const Eigen::Vector3d from(unit(rng), unit(rng), unit(rng));
        const auto shapes = oneShape(std::make_unique<TestOctahedron>(1.0, randomPlacement(rng, r0)));
        const render::Camera camera =
            test::cameraLookingAt(r0 + 6.0 * from.normalized(), r0, 40.0, shapes[0]->bounds());
        const render::Anchor anchor{r0 + Point(3.0, -40.0, 7.0)};
        const snapshot::Image image =
            renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));

        const test::ExactCoverage exact(*shapes[0], camera, kWidth, kHeight);
        test::expectCoversExactly(image, exact);
        EXPECT_GT(exact.hits(), 300) << "the shape should fill a good part of the image";
    }
}

// A renderer of its own, for the options DirectRenderer fixes (translucency) and the real upload path.
class SceneRenderer {
public:
    SceneRenderer() : context_(kWidth, kHeight), renderer_(context_.gl()) {}

    snapshot::Image draw(const std::vector<std::unique_ptr<Shape>>& shapes, const render::Camera& camera,
                         const render::LayerOptions& options, const render::Anchor& anchor) {
        renderer_.setAnchor(anchor);
        render::uploadScene(renderer_, shapes, render::SceneLayers{render::LineBatch(anchor), {}}, options);
        renderer_.draw(camera, options.render, kWidth, kHeight);
        return context_.read();
    }
    render::Renderer& renderer() { return renderer_; }

private:
    snapshot::OsmesaContext context_;
    render::Renderer renderer_;
};

render::LayerOptions blackBackground() {
    render::LayerOptions options;
    options.render.background = {0.0f, 0.0f, 0.0f, 1.0f};
    return options;
}

// Looking at `target` along -(1, 1, 1): an unplaced octahedron's (+, +, +) face is then face-on.
render::Camera diagonalView(const Point& target, const Eigen::AlignedBox3d& bounds) {
    return test::cameraLookingAt(target + 6.0 * Point(1.0, 1.0, 1.0).normalized(), target, 40.0, bounds);
}

// A base whose centre is not at its translation: the shape's bounds centre is r0 + (2, 0, 0). A plane
// between r0 and that centre hides it by the bounds centre (r0 would be kept), and the flipped plane keeps
// it; the upload path (uploadScene) applies the plane.
TEST(MeshSlice, AMeshIsKeptOrHiddenByTheCenterOfItsBounds) {
    const Point r0(10.0, 0.0, 0.0);
    auto octahedron =
        std::make_unique<TestOctahedron>(0.8, AffineTransform(Eigen::Matrix3d::Identity(), r0), Point(2.0, 0.0, 0.0));
    const auto shapes = oneShape(std::move(octahedron));
    const Point center = shapes[0]->bounds().center();
    ASSERT_NEAR((center - Point(12.0, 0.0, 0.0)).norm(), 0.0, 1e-12);
    const render::Camera camera = diagonalView(center, shapes[0]->bounds());
    const render::Anchor anchor{center};
    SceneRenderer renderer;

    render::LayerOptions options = blackBackground();
    EXPECT_GT(coveredPixels(renderer.draw(shapes, camera, options, anchor)), 500);
    options.slice = render::SlicePlane{Point(11.0, 0.0, 0.0), Direction(1.0, 0.0, 0.0)};  // hides x > 11
    EXPECT_EQ(coveredPixels(renderer.draw(shapes, camera, options, anchor)), 0) << "the bounds centre is hidden";
    options.slice = render::SlicePlane{Point(11.0, 0.0, 0.0), Direction(-1.0, 0.0, 0.0)};  // hides x < 11
    EXPECT_GT(coveredPixels(renderer.draw(shapes, camera, options, anchor)), 500) << "the bounds centre is kept";

    const render::ShapeInstances all = render::buildShapeInstances(shapes, anchor);
    EXPECT_TRUE(render::keptShapes(all, shapes, {Point(11.0, 0.0, 0.0), Direction(1.0, 0.0, 0.0)}).meshIds.empty());
    EXPECT_EQ(render::keptShapes(all, shapes, {Point(11.0, 0.0, 0.0), Direction(-1.0, 0.0, 0.0)}).meshIds,
              std::vector<ShapeId>{0});
}

// The pixel at the image centre.
std::array<int, 3> centerPixel(const snapshot::Image& image) {
    const std::uint8_t* p = image.pixel(kWidth / 2, kHeight / 2);
    return {p[0], p[1], p[2]};
}

void expectSameColour(const std::array<int, 3>& a, const std::array<int, 3>& b) {
    for (std::size_t c = 0; c < 3; ++c) EXPECT_LE(std::abs(a[c] - b[c]), kChannelLevels) << "channel " << c;
}

// Seen face-on at the image centre, a mesh face is lit like the front of a droplet there (the headlight
// straight on): the same colour opaque, and translucent the same blend, once; blending its back faces
// too would make it darker-and-bluer by a whole second layer. Selected, it is drawn in kHighlight.
TEST(MeshShading, LitBlendedAndHighlightedLikeADroplet) {
    const Point target(0.0, 0.0, 0.0);
    std::vector<std::unique_ptr<Shape>> octahedron = oneShape(std::make_unique<TestOctahedron>(1.0));
    std::vector<std::unique_ptr<Shape>> sphere = oneShape(std::make_unique<Sphere>(target, 1.0));
    octahedron[0]->setMediumId(1);
    sphere[0]->setMediumId(1);
    const render::Camera camera =
        diagonalView(target, Eigen::AlignedBox3d(Point::Constant(-1.0), Point::Constant(1.0)));
    const render::Anchor anchor{Point(0.5, -0.25, 2.0)};
    SceneRenderer renderer;
    render::LayerOptions options;  // the usual, not black, background: blending shows against it
    const auto colour = [&](const std::vector<std::unique_ptr<Shape>>& shapes) {
        return centerPixel(renderer.draw(shapes, camera, options, anchor));
    };

    const std::array<int, 3> opaque = colour(octahedron);
    const render::Colour water = render::mediumColour(1);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(opaque[c], 255.0 * water[c], kChannelLevels) << "channel " << c;
    expectSameColour(opaque, colour(sphere));

    options.render.translucent = true;
    const std::array<int, 3> blended = colour(octahedron);
    expectSameColour(blended, colour(sphere));
    const float alpha = options.render.opacity;
    for (std::size_t c = 0; c < 3; ++c) {
        const double once = 255.0 * (alpha * water[c] + (1.0f - alpha) * options.render.background[c]);
        EXPECT_NEAR(blended[c], once, kChannelLevels) << "channel " << c;
    }

    options.render.translucent = false;
    options.selected = 0;
    const std::array<int, 3> highlighted = colour(octahedron);
    for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(highlighted[c], 255.0 * render::kHighlight[c], kChannelLevels) << "channel " << c;
    }
}

// The upload path keeps one geometry per base and matrix: moving the shape (a new shape with another r0,
// as an edit makes it) draws it at its new place from the same geometry and buffers, without placing its
// mesh again; another matrix is another geometry; a geometry no shape uses any more is dropped.
TEST(MeshCache, AMovedShapeIsDrawnAtItsNewPlaceFromTheSameGeometry) {
    const Eigen::Matrix3d m = Eigen::Vector3d(1.0, 0.5, 0.8).asDiagonal();
    std::vector<std::unique_ptr<Shape>> shapes =
        oneShape(std::make_unique<TestOctahedron>(1.0, AffineTransform(m, Point(-1.5, 0.0, 0.0))));
    const auto& first = static_cast<const TestOctahedron&>(*shapes[0]);
    const Eigen::AlignedBox3d bounds(Point(-3.0, -1.0, -1.0), Point(3.0, 1.0, 1.0));
    const render::Camera camera = test::cameraLookingAt(Point(0.0, 0.0, 8.0), Point::Zero(), 40.0, bounds);
    const render::Anchor anchor{Point(0.25, 0.0, 0.0)};
    SceneRenderer renderer;
    const render::MeshCache& cache = renderer.renderer().meshCache();
    const auto covered = [&](const snapshot::Image& image, const Point& p) {
        const Eigen::Vector2d pixel = test::projectToPixels(camera, p, kWidth, kHeight);
        return !isBlack(image, static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
    };

    const snapshot::Image before = renderer.draw(shapes, camera, blackBackground(), anchor);
    EXPECT_TRUE(covered(before, Point(-1.5, 0.0, 0.0)));
    EXPECT_FALSE(covered(before, Point(1.5, 0.0, 0.0)));
    EXPECT_EQ(cache.made(), 1u);
    const int meshCalls = first.baseMeshCalls();

    shapes[0] = first.withTransform(AffineTransform(m, Point(1.5, 0.0, 0.0)));
    const snapshot::Image after = renderer.draw(shapes, camera, blackBackground(), anchor);
    EXPECT_FALSE(covered(after, Point(-1.5, 0.0, 0.0)));
    EXPECT_TRUE(covered(after, Point(1.5, 0.0, 0.0)));
    EXPECT_EQ(cache.made(), 1u) << "moved: the same geometry";
    // `first` is gone; the moved shape shares its base, which counts the calls.
    EXPECT_EQ(static_cast<const TestOctahedron&>(*shapes[0]).baseMeshCalls(), meshCalls) << "the mesh was placed again";
    EXPECT_EQ(cache.size(), 1u);

    // Two shapes of one base and matrix share a geometry; another matrix is another one.
    shapes.push_back(
        static_cast<const TestOctahedron&>(*shapes[0]).withTransform(AffineTransform(m, Point(-1.5, 0.0, 0.0))));
    shapes.push_back(
        static_cast<const TestOctahedron&>(*shapes[0]).withTransform(AffineTransform(0.5 * m, Point(0.0, 0.0, 0.0))));
    const snapshot::Image three = renderer.draw(shapes, camera, blackBackground(), anchor);
    EXPECT_TRUE(covered(three, Point(-1.5, 0.0, 0.0)));
    EXPECT_TRUE(covered(three, Point(0.0, 0.0, 0.0)));
    EXPECT_TRUE(covered(three, Point(1.5, 0.0, 0.0)));
    EXPECT_EQ(cache.made(), 2u);
    EXPECT_EQ(cache.size(), 2u);

    shapes.resize(2);
    renderer.draw(shapes, camera, blackBackground(), anchor);
    EXPECT_EQ(cache.size(), 1u) << "the unused geometry is dropped";
}

// The geometry is the placed mesh less r0, in float; the instance puts r0 back, relative to the anchor.
TEST(MeshCache, GeometryAndInstanceAddUpToThePlacedMesh) {
    std::mt19937_64 rng(5);
    const Point r0(1e4, -2e4, 3.5e3);
    const auto shapes = oneShape(std::make_unique<TestOctahedron>(0.3, randomPlacement(rng, r0)));
    const auto& shape = static_cast<const GeneralShape&>(*shapes[0]);
    const render::Anchor anchor{r0 + Point(0.5, 0.5, -0.5)};
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);
    ASSERT_EQ(instances.meshes.size(), 1u);
    EXPECT_EQ(instances.meshIds, std::vector<ShapeId>{0});
    EXPECT_TRUE(instances.rounded.empty());
    EXPECT_TRUE(instances.boxes.empty());
    const render::MeshInstance& drawn = instances.meshes[0];
    const SurfaceMesh mesh = shape.mesh();
    ASSERT_EQ(drawn.geometry->vertices.size(), mesh.vertices.size());
    ASSERT_EQ(drawn.geometry->indices.size(), 3 * mesh.triangles.size());
    // float: a relative rounding of 6e-8 of the shape's size and of the anchor offset.
    constexpr double kFloatRounding = 1e-6;
    const Point center(drawn.instance.center[0], drawn.instance.center[1], drawn.instance.center[2]);
    for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
        const auto& v = drawn.geometry->vertices[k];
        const Point world = anchor.origin + center + Point(v.position[0], v.position[1], v.position[2]);
        EXPECT_NEAR((world - mesh.vertices[k]).norm(), 0.0, kFloatRounding) << "vertex " << k;
        EXPECT_NEAR((Eigen::Vector3d(v.normal[0], v.normal[1], v.normal[2]) - mesh.normals[k]).norm(), 0.0,
                    kFloatRounding);
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(drawn.geometry->indices[3 * t + c], mesh.triangles[t][c]);
    }
}

// A square pyramid's apex, shared by four faces, with its true normal (up) kept, a normal lying across
// the surface (as the engine's Bezier poles had, drawn as dark spikes) or a NaN one replaced by the mean
// of its faces, and a base corner's normal 54.7 degrees off its faces' mean (a sharp corner) kept.
TEST(MeshNormals, ANormalAcrossTheSurfaceIsReplacedByItsTrianglesMean) {
    SurfaceMesh mesh;
    mesh.vertices = {Point(0, 0, 1), Point(1, 1, 0), Point(-1, 1, 0), Point(-1, -1, 0), Point(1, -1, 0)};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    const Eigen::Vector3d corner = Eigen::Vector3d(1, 1, 0).normalized();
    for (const Eigen::Vector3d& apex :
         {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0),
          Eigen::Vector3d(Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()))}) {
        mesh.normals = {apex, corner, Eigen::Vector3d(-1, 1, 0).normalized(), Eigen::Vector3d(-1, -1, 0).normalized(),
                        Eigen::Vector3d(1, -1, 0).normalized()};
        const std::vector<Eigen::Vector3d> drawn = render::drawnNormals(mesh);
        ASSERT_EQ(drawn.size(), mesh.vertices.size());
        EXPECT_NEAR((drawn[0] - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-15) << apex.transpose();
        EXPECT_EQ(drawn[1], corner) << "a corner's normal is kept";
    }
}

}  // namespace
}  // namespace dropscope
