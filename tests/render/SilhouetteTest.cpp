// Shapes land where the camera math and the engine's geometry say: the silhouettes of a sphere and of
// rotated ellipsoids, pixel by pixel, without golden images.
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"
#include "render/RenderHarness.hpp"
#include "render/RenderTolerances.hpp"
#include "render/SilhouetteCoverage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using test::DirectRenderer;
using test::isBlack;
using test::oneShape;

constexpr int kWidth = 160;  // not square: a wrong aspect ratio shows as an ellipse
constexpr int kHeight = 120;

// Looking at `target` from `distance` along `fromDirection`, 40 degrees high.
render::Camera lookingAt(const Point& target, const Eigen::Vector3d& fromDirection, double distance,
                         const Eigen::AlignedBox3d& bounds) {
    return test::cameraLookingAt(target + distance * fromDirection.normalized(), target, 40.0, bounds);
}

// A sphere away from the origin (so the anchor matters), seen obliquely with the view axis through its
// centre: its silhouette is the circle of angular radius asin(r / d) about the image centre.
TEST(SphereSilhouette, CenteredSphereCoversTheCircleTheCameraMathPredicts) {
    const Point center(3.0, -2.0, 5.0);
    const double radius = 1.0;
    const double distance = 5.0;
    const auto shapes = oneShape(std::make_unique<Sphere>(center, radius));
    const render::Camera camera = lookingAt(center, {1.0, 0.5, 2.0}, distance, shapes[0]->bounds());
    const render::Anchor anchor{center};

    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image image =
        renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));

    const Eigen::Vector2d middle = test::projectToPixels(camera, center, kWidth, kHeight);
    ASSERT_NEAR(middle.x(), 0.5 * kWidth, 1e-9);
    ASSERT_NEAR(middle.y(), 0.5 * kHeight, 1e-9);
    const double halfHeight = std::tan(camera.fovDeg * std::numbers::pi / 360.0);
    const double expectedRadius = 0.5 * kHeight * std::tan(std::asin(radius / distance)) / halfHeight;

    EXPECT_FALSE(isBlack(image, kWidth / 2, kHeight / 2)) << "the centre pixel is not coloured";
    const int outside = static_cast<int>(std::lround(middle.x() + 1.5 * expectedRadius));
    ASSERT_LT(outside, kWidth);
    EXPECT_TRUE(isBlack(image, outside, kHeight / 2)) << "a pixel at 1.5 radii is coloured";

    // Signed distance of a pixel centre from the projected circle, in pixels.
    const auto fromCircle = [&](int x, int y) {
        return (Eigen::Vector2d(x + 0.5, y + 0.5) - middle).norm() - expectedRadius;
    };
    const test::CoverageAgreement agreement = test::compareCoverage(
        image, [&](int x, int y) { return fromCircle(x, y) < 0.0; },
        [&](int x, int y) { return std::abs(fromCircle(x, y)) <= test::kSilhouetteBandPixels; },
        [&](int x, int y) { return ", " + std::to_string(fromCircle(x, y)) + " px from the circle"; });
    EXPECT_EQ(agreement.outsideBand, 0) << "pixels farther than " << test::kSilhouetteBandPixels
                                        << " px from the projected circle (radius " << expectedRadius
                                        << " px) decided wrongly";
    EXPECT_LE(agreement.bandMismatches, test::kBandMismatchShare * agreement.band)
        << "of " << agreement.band << " pixels along the circle";
    const double areaRadius = std::sqrt(test::coveredPixels(image) / std::numbers::pi);
    EXPECT_NEAR(areaRadius, expectedRadius, test::kAreaRadiusPixels);
}

// The harness's pinhole rays and Camera::project are the same camera: projecting a point along the ray
// through a pixel centre gives back that centre.
TEST(SphereSilhouette, PixelRaysAndCameraProjectAgree) {
    const render::Camera camera =
        lookingAt({1.0, 2.0, -3.0}, {-0.3, 0.8, 0.6}, 7.0, Eigen::AlignedBox3d(Point(0, 1, -4), Point(2, 3, -2)));
    const Point eye(camera.eye.x, camera.eye.y, camera.eye.z);
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {159, 0}, {80, 60}, {17, 101}, {159, 119}}) {
        const Point along = eye + 6.0 * test::pixelRay(camera, i, j, kWidth, kHeight).vector();
        const Eigen::Vector2d back = test::projectToPixels(camera, along, kWidth, kHeight);
        EXPECT_NEAR(back.x(), i + 0.5, 1e-6) << i << "," << j;
        EXPECT_NEAR(back.y(), j + 0.5, 1e-6) << i << "," << j;
    }
}

// Seeded random ellipsoids (semi-axes, rotation, place) from random directions: every pixel the engine's
// distanceToSurface hits is covered and every pixel it misses is background; in the one-pixel band along
// the silhouette (a pixel with an 8-neighbour classified the other way), at most kBandMismatchShare differ.
TEST(EllipsoidSilhouette, RotatedEllipsoidsCoverExactlyThePixelsWhoseRaysHitTheEngineShape) {
    DirectRenderer renderer(kWidth, kHeight);
    for (int k = 0; k < 6; ++k) {
        SCOPED_TRACE("case " + std::to_string(k));
        std::mt19937_64 rng(static_cast<std::uint64_t>(k));
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::uniform_real_distribution<double> semi(0.3, 1.3);
        const Direction axis(unit(rng), unit(rng), unit(rng));
        const double angle = std::numbers::pi * unit(rng);
        const Point center(5.0 * unit(rng), 5.0 * unit(rng), 5.0 * unit(rng));
        const Eigen::Vector3d semiAxes(semi(rng), semi(rng), semi(rng));
        const Eigen::Vector3d from(unit(rng), unit(rng), unit(rng));
        const auto shapes = oneShape(
            std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(center, semiAxes, rotationAboutAxis(axis, angle))));
        const render::Camera camera = lookingAt(center, from, 6.0, shapes[0]->bounds());
        const render::Anchor anchor{center};
        const snapshot::Image image =
            renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));

        const test::ExactCoverage engine(*shapes[0], camera, kWidth, kHeight);
        test::expectCoversExactly(image, engine);
        EXPECT_GT(engine.hits(), 300) << "the ellipsoid should fill a good part of the image";
    }
}

// The shapes drawn with each RenderOptions::pointPixels in turn, each drawing against the engine's coverage.
void expectCoversExactlyWithPointPixels(DirectRenderer& renderer, const render::Camera& camera,
                                        const render::Anchor& anchor, const std::vector<std::unique_ptr<Shape>>& shapes,
                                        const test::ExactCoverage& engine, std::initializer_list<float> settings) {
    for (const float pointPixels : settings) {
        SCOPED_TRACE("pointPixels " + std::to_string(pointPixels));
        renderer.setPointPixels(pointPixels);
        const snapshot::Image image =
            renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));
        test::expectCoversExactly(image, engine);
    }
}

// A crowd of small spheres and rotated ellipsoids, 1 to 11 pixels across, some across the image's edges and
// some outside it, more than one chunk of them (Renderer::drawRounded): whichever of them are quads, points
// with exact depth or points with the front's depth, the drawing covers exactly the pixels whose rays meet
// some shape. So no shape is culled while in view, dropped between the variants, or drawn as a point too
// small for it.
TEST(SmallShapeSilhouettes, QuadsAndPointsCoverExactlyThePixelsWhoseRaysHitAShape) {
    DirectRenderer renderer(kWidth, kHeight);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> size(0.06, 0.7);
    // Three draws for one vector, z first: the crowd GCC built when they were the arguments of one call, whose
    // order of evaluation is the compiler's (clang's, left to right, built another crowd).
    const auto draw3 = [&rng](std::uniform_real_distribution<double>& d) {
        const double z = d(rng);
        const double y = d(rng);
        return Eigen::Vector3d(d(rng), y, z);
    };
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int k = 0; k < 700; ++k) {
        const Point center = draw3(unit).cwiseProduct(Eigen::Vector3d(12.0, 8.0, 4.0));
        if (k % 3 == 0) {
            const Eigen::Vector3d semiAxes = draw3(size);
            const Direction axis(draw3(unit));
            shapes.push_back(std::make_unique<Ellipsoid>(
                Ellipsoid::fromSemiAxes(center, semiAxes, rotationAboutAxis(axis, std::numbers::pi * unit(rng)))));
        } else {
            shapes.push_back(std::make_unique<Sphere>(center, size(rng)));
        }
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    const render::Camera camera = lookingAt(Point(0.5, -0.3, 0.0), Eigen::Vector3d(0.2, 0.3, 1.0), 22.0, bounds);
    const render::Anchor anchor{Point(0.5, -0.3, 0.0)};
    const test::ExactCoverage engine(shapes, camera, kWidth, kHeight);
    EXPECT_GT(engine.hits(), 2000) << "the shapes should cover a good part of the image";
    // 0: quads at the edges, exact points inside; 4: also points with the front's depth; 16: those inside.
    expectCoversExactlyWithPointPixels(renderer, camera, anchor, shapes, engine, {0.0f, 4.0f, 16.0f});
}

// The same under a 90-degree field of view, where shapes off the axis are widened most and points up to 32
// pixels are drawn (their square must cover the silhouette's outer side), 257 shapes: a chunk of 256 and
// one of a single shape.
TEST(SmallShapeSilhouettes, WideFieldOfViewPointsCoverTheirSilhouettes) {
    DirectRenderer renderer(kWidth, kHeight);
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> size(0.15, 2.2);
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int k = 0; k < 257; ++k) {
        shapes.push_back(
            std::make_unique<Sphere>(Point(14.0 * unit(rng), 11.0 * unit(rng), 3.0 * unit(rng)), size(rng)));
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    const render::Camera camera = test::cameraLookingAt(Point(0.0, 0.0, 14.0), Point(0.0, 0.0, 0.0), 90.0, bounds);
    const render::Anchor anchor{Point(0.0, 0.0, 0.0)};
    const test::ExactCoverage engine(shapes, camera, kWidth, kHeight);
    EXPECT_GT(engine.hits(), 3000);
    expectCoversExactlyWithPointPixels(renderer, camera, anchor, shapes, engine, {0.0f, 32.0f});
}

// Runs of spheres drawn as points by the sphere programs (a radius passed, not two matrices) give the very
// pixels the general programs give: 1200 spheres 1 to 20 pixels across (five chunks of 256 or fewer) and one
// ellipsoid, whose chunk the general programs draw either way.
TEST(SmallShapeSilhouettes, TheSphereProgramsDrawTheSamePixelsAsTheGeneralOnes) {
    DirectRenderer renderer(kWidth, kHeight);
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> size(0.04, 0.6);
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int k = 0; k < 1200; ++k) {
        const double x = unit(rng);
        const double y = unit(rng);
        const double z = unit(rng);
        shapes.push_back(std::make_unique<Sphere>(Point(12.0 * x, 8.0 * y, 6.0 * z), size(rng)));
    }
    shapes.push_back(std::make_unique<Ellipsoid>(
        Ellipsoid::fromSemiAxes(Point(2.0, 1.0, 0.0), Eigen::Vector3d(0.5, 0.3, 0.2), Eigen::Matrix3d::Identity())));
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    const render::Camera camera = lookingAt(Point(0.5, -0.3, 0.0), Eigen::Vector3d(0.2, 0.3, 1.0), 26.0, bounds);
    const render::Anchor anchor{Point(0.5, -0.3, 0.0)};
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);
    int differing = 0;
    int lit = 0;
    for (const float pointPixels : {0.0f, 6.0f, 32.0f}) {
        renderer.setPointPixels(pointPixels);
        renderer.setSphereProgram(false);
        const snapshot::Image general = renderer.draw(camera, anchor, instances, render::LineBatch(anchor));
        renderer.setSphereProgram(true);
        const snapshot::Image spheres = renderer.draw(camera, anchor, instances, render::LineBatch(anchor));
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                lit += test::isBlack(general, x, y) ? 0 : 1;
                differing += test::samePixel(spheres, x, y, general.pixel(x, y)) ? 0 : 1;
            }
        }
    }
    EXPECT_GT(lit, 3 * kWidth * kHeight / 4) << "the spheres should cover most of the image";
    EXPECT_EQ(differing, 0);
}

// Every sphere's instance is one the sphere programs take (else they would never run, and the test above could
// not fail), whatever its radius and place; an ellipsoid's, even with equal semi-axes but turned, is not.
TEST(SmallShapeSilhouettes, SpheresAndOnlySpheresAreSphereInstances) {
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> exponent(-6.0, 4.0);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const render::Anchor anchor{Point(0.3, -7.0, 2.0)};
    for (int k = 0; k < 1000; ++k) {
        const double radius = std::pow(10.0, exponent(rng));
        const double x = unit(rng);
        const double y = unit(rng);
        const double z = unit(rng);
        const Point center = 1e3 * Point(x, y, z);
        ASSERT_TRUE(render::isSphereInstance(render::sphereInstance(center, radius, anchor, render::kHighlight)))
            << "radius " << radius;
    }
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(1.0, 2.0, 3.0), 0.7));
    shapes.push_back(std::make_unique<Ellipsoid>(
        Ellipsoid::fromSemiAxes(Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.5, 0.4, 0.3), Eigen::Matrix3d::Identity())));
    shapes.push_back(std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(
        Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.5, 0.5, 0.5), rotationAboutAxis(Direction(1.0, 2.0, 3.0), 0.4))));
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);
    ASSERT_EQ(instances.rounded.size(), 3U);
    EXPECT_TRUE(render::isSphereInstance(instances.rounded[0]));
    EXPECT_FALSE(render::isSphereInstance(instances.rounded[1]));
    EXPECT_FALSE(render::isSphereInstance(instances.rounded[2]));
}

// Event markers and handles (Renderer::setMarkers) go through the quad program alone, whatever their size:
// small ones too cover exactly the pixels of their spheres; so they do drawn on the processor.
TEST(MarkerSilhouettes, SmallAndLargeMarkersCoverExactlyThePixelsOfTheirSpheres) {
    DirectRenderer renderer(kWidth, kHeight);
    renderer.setPointPixels(6.0f);
    std::vector<std::unique_ptr<Shape>> spheres;
    for (int k = 0; k < 12; ++k) {
        const double radius = 0.05 + 0.06 * k;  // about 1 to 15 pixels across
        spheres.push_back(std::make_unique<Sphere>(Point(-5.5 + 1.0 * k, 1.5 * std::sin(k), 0.0), radius));
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& sphere : spheres) bounds.extend(sphere->bounds());
    const render::Camera camera = lookingAt(Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.2, 1.0), 16.0, bounds);
    const render::Anchor anchor{Point(0.0, 0.0, 0.0)};
    std::vector<render::ShapeInstance> markers;
    for (const auto& sphere : spheres) {
        const auto& s = static_cast<const Sphere&>(*sphere);
        markers.push_back(render::sphereInstance(s.center(), s.radius(), anchor, render::kHighlight));
    }
    const test::ExactCoverage engine(spheres, camera, kWidth, kHeight);
    EXPECT_GT(engine.hits(), 500);
    for (const bool processor : {false, true}) {  // by OpenGL, and on the processor (render/CpuRasteriser)
        SCOPED_TRACE(processor ? "on the processor" : "by OpenGL");
        renderer.setProcessorRaster(processor);
        const snapshot::Image image = renderer.draw(camera, anchor, {}, render::LineBatch(anchor), markers);
        EXPECT_EQ(renderer.lastFrameOnProcessor(), processor);
        test::expectCoversExactly(image, engine);
    }
}

}  // namespace
}  // namespace dropscope
