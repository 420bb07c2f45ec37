// Frames drawn on the processor (render/CpuRasteriser, RenderOptions::processorRaster): the pixels the engine's
// own geometry says, the depth and shading of the camera's closed forms, the picture OpenGL draws, and OpenGL
// whenever the frame holds what the processor does not draw.
#include "geometry/Box.hpp"
#include "geometry/Sphere.hpp"
#include "render/CpuRasteriser.hpp"
#include "render/ImageComparison.hpp"
#include "render/LayoutComparison.hpp"
#include "render/RenderHarness.hpp"
#include "render/RenderTolerances.hpp"
#include "render/SilhouetteCoverage.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace dropscope {
namespace {

using test::DirectRenderer;

constexpr int kWidth = 160;  // not square: a wrong aspect ratio shows as an ellipse
constexpr int kHeight = 120;

render::Camera lookingAt(const Point& target, const Eigen::Vector3d& fromDirection, double distance, double fovDeg,
                         const Eigen::AlignedBox3d& bounds) {
    return test::cameraLookingAt(target + distance * fromDirection.normalized(), target, fovDeg, bounds);
}

// Looking at the origin from `eye`, up +y, with the given near and far planes.
render::Camera towardOrigin(const glm::dvec3& eye, double nearPlane, double farPlane) {
    render::Camera camera;
    camera.eye = eye;
    camera.target = {0.0, 0.0, 0.0};
    camera.nearPlane = nearPlane;
    camera.farPlane = farPlane;
    return camera;
}

std::vector<std::unique_ptr<Shape>> sphereCrowd(int count, double spread, double smallest, double largest,
                                                unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> size(smallest, largest);
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int k = 0; k < count; ++k) {
        const double x = unit(rng);
        const double y = unit(rng);
        const double z = unit(rng);
        shapes.push_back(std::make_unique<Sphere>(Point(1.5 * spread * x, spread * y, 0.5 * spread * z), size(rng)));
    }
    return shapes;
}

Eigen::AlignedBox3d boundsOf(const std::vector<std::unique_ptr<Shape>>& shapes) {
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    return bounds;
}

// A crowd of spheres 1 to 11 pixels across, some across the image's edges and some outside it, under a 40 and a
// 90 degree field of view (where spheres off the axis are widened most): the processor's frame covers exactly the
// pixels whose eye rays meet some sphere (the engine's distanceToSurface), as OpenGL's does
// (SmallShapeSilhouettes).
TEST(ProcessorRaster, SpheresCoverExactlyThePixelsWhoseRaysHitThem) {
    DirectRenderer renderer(kWidth, kHeight);
    renderer.setProcessorRaster(true);
    const auto shapes = sphereCrowd(700, 8.0, 0.06, 0.7, 11);
    const Eigen::AlignedBox3d bounds = boundsOf(shapes);
    const render::Anchor anchor{Point(0.5, -0.3, 0.0)};
    for (const auto& [fovDeg, distance] : {std::pair{40.0, 22.0}, std::pair{90.0, 9.0}}) {
        SCOPED_TRACE("field of view " + std::to_string(fovDeg));
        const render::Camera camera =
            lookingAt(Point(0.5, -0.3, 0.0), Eigen::Vector3d(0.2, 0.3, 1.0), distance, fovDeg, bounds);
        const snapshot::Image image =
            renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));
        ASSERT_TRUE(renderer.lastFrameOnProcessor());
        const test::ExactCoverage engine(shapes, camera, kWidth, kHeight);
        EXPECT_GT(engine.hits(), 2000) << "the spheres should cover a good part of the image";
        test::expectCoversExactly(image, engine);
    }
}

// Spheres 12 to 40 pixels across, whose squares' blocks reach well beyond their silhouettes, cover exactly the
// pixels whose eye rays meet some sphere, as the small ones do.
TEST(ProcessorRaster, WideSpheresCoverExactlyThePixelsWhoseRaysHitThem) {
    DirectRenderer renderer(kWidth, kHeight);
    renderer.setProcessorRaster(true);
    const auto shapes = sphereCrowd(30, 4.0, 0.3, 1.0, 13);
    const Eigen::AlignedBox3d bounds = boundsOf(shapes);
    const render::Anchor anchor{Point(0.0, 0.0, 0.0)};
    for (const auto& [fovDeg, distance] : {std::pair{40.0, 9.0}, std::pair{90.0, 5.0}}) {
        SCOPED_TRACE("field of view " + std::to_string(fovDeg));
        const render::Camera camera =
            lookingAt(Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.2, 0.3, 1.0), distance, fovDeg, bounds);
        const snapshot::Image image =
            renderer.draw(camera, anchor, render::buildShapeInstances(shapes, anchor), render::LineBatch(anchor));
        ASSERT_TRUE(renderer.lastFrameOnProcessor());
        const test::ExactCoverage engine(shapes, camera, kWidth, kHeight);
        EXPECT_GT(engine.hits(), kWidth * kHeight / 4) << "the spheres should cover a good part of the image";
        EXPECT_LT(engine.hits(), kWidth * kHeight * 9 / 10) << "and leave some of it";
        test::expectCoversExactly(image, engine);
    }
}

// A sphere around the eye (a marker there): seen from inside, every pixel is its far side.
TEST(ProcessorRaster, ASphereAroundTheEyeCoversEveryPixel) {
    DirectRenderer renderer(kWidth, kHeight);
    renderer.setProcessorRaster(true);
    const render::Anchor anchor{Point(0.0, 0.0, 0.0)};
    const Point eye(3.0, 2.0, 16.0);
    const render::Camera camera = test::cameraLookingAt(
        eye, Point(0.0, 0.0, 0.0), 40.0, Eigen::AlignedBox3d(Point(-1.0, -1.0, -1.0), Point(1.0, 1.0, 1.0)));
    const std::vector<render::ShapeInstance> around{render::sphereInstance(eye, 0.5, anchor, render::kHighlight)};
    const snapshot::Image inside = renderer.draw(camera, anchor, {}, render::LineBatch(anchor), around);
    EXPECT_TRUE(renderer.lastFrameOnProcessor());
    EXPECT_EQ(test::coveredPixels(inside), kWidth * kHeight);
}

// One sphere seen from the front, drawn by rasterise alone: at the pixels about its centre's image the depth is
// that of the point the eye ray meets (Camera::project of the exact hit, in double) and the colour the headlight's
// 0.3 + 0.7 cos(angle between the normal and the ray) times the sphere's.
TEST(ProcessorRaster, ASpheresDepthAndShadeAreThoseOfTheHitThePixelsRayMeets) {
    const Point centre(0.4, -0.2, 0.3);
    const double radius = 0.8;
    const Sphere sphere(centre, radius);
    const render::Camera camera =
        lookingAt(Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.3, 0.4, 1.0), 6.0, 40.0, sphere.bounds());
    const render::RasterView view = render::rasterView(camera, kWidth, kHeight);
    const render::Colour colour{0.2f, 0.6f, 0.9f, 1.0f};
    const std::vector<render::RasterSphere> spheres{{glm::vec3(centre.x(), centre.y(), centre.z()),
                                                     static_cast<float>(radius), static_cast<float>(1.0 / radius),
                                                     colour}};
    render::RasterImage image;
    render::rasterise({spheres, {}, {}}, view, {0.0f, 0.0f, 0.0f, 1.0f}, image, 2);

    int checked = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const Direction ray = test::pixelRay(camera, i, j, kWidth, kHeight);
            const Point eye(camera.eye.x, camera.eye.y, camera.eye.z);
            const double t = sphere.distanceToSurface(eye, ray);
            const int row = kHeight - 1 - j;  // the image's rows go up, the pixels' down
            if (!std::isfinite(t)) continue;
            const Point hit = eye + t * ray.vector();
            const Eigen::Vector3d normal = (hit - centre).normalized();
            // Within a pixel of the rim the shade changes fastest and a pixel's centre may fall either side.
            const double cosine = std::abs(normal.dot(ray.vector()));
            if (cosine < 0.2) continue;
            const glm::dvec3 projected = camera.project({hit.x(), hit.y(), hit.z()}, kWidth, kHeight);
            EXPECT_NEAR(image.depthAt(i, row), projected.z, 1e-5) << "pixel " << i << ", " << j;
            const std::uint32_t pixel = image.colourAt(i, row);
            for (int channel = 0; channel < 3; ++channel) {
                const double expected = 255.0 * colour[static_cast<std::size_t>(channel)] * (0.3 + 0.7 * cosine);
                EXPECT_NEAR(static_cast<double>((pixel >> (8 * channel)) & 0xFFu), expected, 1.0)
                    << "pixel " << i << ", " << j << ", channel " << channel;
            }
            EXPECT_EQ(pixel >> 24, 255u);
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

// Two overlapping spheres and a segment passing behind one and in front of the other: the nearest wins at every
// pixel, in either order of the spheres (bit for bit).
TEST(ProcessorRaster, TheNearestWinsInAnyOrder) {
    const render::Colour red{1.0f, 0.0f, 0.0f, 1.0f};
    const render::Colour blue{0.0f, 0.0f, 1.0f, 1.0f};
    const render::Colour green{0.0f, 1.0f, 0.0f, 1.0f};
    std::vector<render::RasterSphere> spheres{{glm::vec3(-0.3f, 0.0f, 0.0f), 0.6f, 1.0f / 0.6f, red},
                                              {glm::vec3(0.3f, 0.1f, 1.0f), 0.5f, 1.0f / 0.5f, blue}};
    // Along x at z = 0.75: in front of the red sphere's surface (z <= 0.6), behind the blue one's front (z = 1.5).
    const std::vector<render::LineVertex> lines{{{-1.5f, 0.05f, 0.75f}, green}, {{1.5f, 0.05f, 0.75f}, green}};
    const render::Camera camera = towardOrigin({0.0, 0.0, 6.0}, 1.0, 20.0);
    const render::RasterView view = render::rasterView(camera, kWidth, kHeight);
    const auto draw = [&](const std::vector<render::RasterSphere>& given, unsigned threads) {
        render::RasterImage image;
        image.resize(3, 5);  // another picture's size: made the view's
        render::rasterise({given, {}, lines}, view, {0.0f, 0.0f, 0.0f, 1.0f}, image, threads);
        return image;
    };
    const render::RasterImage first = draw(spheres, 1);
    const auto at = [&](const glm::dvec3& world) {
        const glm::dvec3 p = camera.project(world, kWidth, kHeight);
        return first.colourAt(static_cast<int>(p.x), kHeight - 1 - static_cast<int>(p.y));
    };
    const std::uint32_t hidden = at({0.0, 0.05, 1.1});  // shaded: only its blue channel lit
    EXPECT_TRUE((hidden & 0xFFFFu) == 0 && (hidden >> 16 & 0xFFu) > 200) << "the blue sphere hides the segment and "
                                                                            "the red one: "
                                                                         << std::hex << hidden;
    EXPECT_EQ(at({-0.7, 0.05, 0.75}), render::packColour(green)) << "the segment lies in front of the red sphere";
    EXPECT_EQ(at({1.3, 0.05, 0.75}), render::packColour(green)) << "the segment beyond the spheres";
    std::swap(spheres[0], spheres[1]);
    const render::RasterImage swapped = draw(spheres, 1);
    EXPECT_EQ(swapped.colour(), first.colour());
    EXPECT_EQ(swapped.depth(), first.depth());
}

// A horizontal and a vertical segment reaching far beyond the picture's edges colour every pixel of their row and
// column, the first and last included, however the rows are cut into strips.
TEST(ProcessorRaster, SegmentsAcrossThePictureReachItsEdges) {
    const render::Colour green{0.0f, 1.0f, 0.0f, 1.0f};
    const render::Camera camera = towardOrigin({0.0, 0.0, 6.0}, 1.0, 20.0);
    const std::vector<render::LineVertex> lines{{{-100.0f, 0.3f, 0.0f}, green},
                                                {{100.0f, 0.3f, 0.0f}, green},
                                                {{0.42f, -100.0f, 0.0f}, green},
                                                {{0.42f, 100.0f, 0.0f}, green}};
    const glm::dvec3 onRow = camera.project({0.0, 0.3, 0.0}, kWidth, kHeight);      // y counted from the top
    const glm::dvec3 onColumn = camera.project({0.42, 0.0, 0.0}, kWidth, kHeight);  // x from the left
    // Well inside a pixel, so rounding cannot move either segment to the next row or column.
    ASSERT_GT(std::abs(onRow.y - std::round(onRow.y)), 0.1);
    ASSERT_GT(std::abs(onColumn.x - std::round(onColumn.x)), 0.1);
    const int row = kHeight - 1 - static_cast<int>(onRow.y);
    const int column = static_cast<int>(onColumn.x);
    const render::RasterView view = render::rasterView(camera, kWidth, kHeight);
    for (const int stripRows : {1, render::kRasterStripRows, kHeight}) {
        render::RasterImage image;
        render::rasterise({{}, {}, lines}, view, {0.0f, 0.0f, 0.0f, 1.0f}, image, 2, render::RasterCode::fastest,
                          stripRows);
        int missed = 0;
        for (int x = 0; x < kWidth; ++x) missed += image.colourAt(x, row) == render::packColour(green) ? 0 : 1;
        for (int y = 0; y < kHeight; ++y) missed += image.colourAt(column, y) == render::packColour(green) ? 0 : 1;
        EXPECT_EQ(missed, 0) << "strips of " << stripRows << " rows";
    }
}

// 300 spheres and 400 segments every way (steep, shallow, diagonal, across the image's edges), half of them
// shaded from one colour to another, seen from (1, 2, 9), over a background whose red and blue differ.
struct RasterCrowd {
    std::vector<render::RasterSphere> spheres;
    std::vector<render::LineVertex> lines;
    render::RasterView view;

    RasterCrowd() {
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        for (int k = 0; k < 300; ++k) {
            const float radius = 0.05f + 0.2f * (unit(rng) + 1.0f);
            spheres.push_back({glm::vec3(3.0f * unit(rng), 2.0f * unit(rng), 2.0f * unit(rng)),
                               radius,
                               1.0f / radius,
                               {0.5f + 0.5f * unit(rng), 0.5f, 0.8f, 1.0f}});
        }
        for (int k = 0; k < 400; ++k) {
            const render::Colour a{1.0f, 0.5f + 0.5f * unit(rng), 0.0f, 1.0f};
            const render::Colour b = k % 2 == 0 ? a : render::Colour{0.0f, 0.3f, 1.0f, 1.0f};
            lines.push_back({{5.0f * unit(rng), 4.0f * unit(rng), 3.0f * unit(rng)}, a});
            lines.push_back({{5.0f * unit(rng), 4.0f * unit(rng), 3.0f * unit(rng)}, b});
        }
        view = render::rasterView(towardOrigin({1.0, 2.0, 9.0}, 0.5, 30.0), kWidth, kHeight);
    }

    render::RasterImage draw(unsigned threads, render::RasterCode code = render::RasterCode::fastest,
                             render::PixelLayout layout = {}, int stripRows = render::kRasterStripRows) const {
        render::RasterImage image;
        image.setLayout(layout);
        render::rasterise({spheres, {}, lines}, view, {0.3f, 0.1f, 0.05f, 1.0f}, image, threads, code, stripRows);
        return image;
    }
};

// The crowd: any number of threads and any strips (across their seams) draw the same picture bit for bit, and the
// baseline copy of the code the same but for rounding. The whole picture as one strip is the reference: a sphere
// or segment a strip wrongly passes over (its rows or its run's worked out short) leaves a seam's rows out.
TEST(ProcessorRaster, AnyNumberOfThreadsOrStripsAndEitherCopyOfTheCodeDrawTheSamePicture) {
    const RasterCrowd crowd;
    ASSERT_GT(crowd.spheres.size(), 4u * 64u) << "several runs of spheres";
    const render::RasterImage one = crowd.draw(1, render::RasterCode::fastest, {}, kHeight);
    int drawn = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) drawn += one.depthAt(x, y) < 1.0f ? 1 : 0;
    }
    EXPECT_GT(drawn, kWidth * kHeight / 3);
    for (const unsigned threads : {1u, 2u, 3u, 5u, 8u}) {
        for (const int stripRows : {1, 2, 7, render::kRasterStripRows, kHeight - 1, 10 * kHeight}) {
            const render::RasterImage other = crowd.draw(threads, render::RasterCode::fastest, {}, stripRows);
            EXPECT_EQ(other.colour(), one.colour()) << threads << " threads, strips of " << stripRows << " rows";
            EXPECT_EQ(other.depth(), one.depth()) << threads << " threads, strips of " << stripRows << " rows";
        }
    }
    if (!render::rasterCodeHasAvx2()) GTEST_SKIP() << "the fastest copy is the baseline's on this processor";
    // The AVX2 copy fuses multiply-adds: a pixel whose centre lies within rounding of a rim or a line's pixel
    // boundary may go the other way, and a shade round to the other level; 1 pixel of 19,200 does here.
    const render::RasterImage baseline = crowd.draw(2, render::RasterCode::baseline);
    int differing = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const std::uint32_t a = baseline.colourAt(x, y);
            const std::uint32_t b = one.colourAt(x, y);
            // A depth near 0.95 is z / w of two sums: a few float steps of rounding there are some 1e-6.
            bool differs = std::abs(baseline.depthAt(x, y) - one.depthAt(x, y)) > 1e-5f;
            for (int channel = 0; channel < 4; ++channel) {
                const int shift = 8 * channel;
                differs = differs ||
                          std::abs(static_cast<int>((a >> shift) & 0xFFu) - static_cast<int>((b >> shift) & 0xFFu)) > 1;
            }
            differing += differs ? 1 : 0;
        }
    }
    EXPECT_LE(differing, kWidth * kHeight / 1000) << "pixels differing between the baseline and the AVX2 code";
}

// The crowd drawn in each layout a framebuffer may have (the top row or the bottom one first, RGBA or BGRA) is the
// same picture, pixel for pixel and in depth: read from memory row by row, each layout's rows and bytes are
// OpenGL's layout's in its own order (the spheres', the segments' and the background's red and blue differ, so
// bytes left unswapped show, and so does a row order reversed: the top and bottom rows differ).
TEST(ProcessorRaster, EveryLayoutHoldsTheSamePicture) {
    const RasterCrowd crowd;
    const render::RasterImage opengl = crowd.draw(2);
    ASSERT_NE(std::vector<std::uint32_t>(opengl.colour().begin(), opengl.colour().begin() + kWidth),
              std::vector<std::uint32_t>(opengl.colour().end() - opengl.stride(),
                                         opengl.colour().end() - opengl.stride() + kWidth));
    for (const render::PixelLayout layout : test::kEveryLayout) {
        SCOPED_TRACE(test::layoutName(layout));
        const render::RasterImage image = crowd.draw(2, render::RasterCode::fastest, layout);
        ASSERT_EQ(image.stride(), opengl.stride());
        EXPECT_EQ(test::differingInMemory(image, opengl, true), 0);
    }
}

// Nothing a scene could hold makes the processor fail: spheres of radius 0 or far below float's reach, NaN colours
// and positions, infinite and coincident ends of segments. Each is left out or drawn, never a crash, and the valid
// sphere beside them is drawn.
TEST(ProcessorRaster, DegenerateSpheresAndSegmentsAreDrawnOrLeftOutSafely) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    const render::Colour red{1.0f, 0.0f, 0.0f, 1.0f};
    const std::vector<render::RasterSphere> spheres{
        {glm::vec3(0.0f), 0.5f, 2.0f, red},
        {glm::vec3(1.0f, 0.0f, 0.0f), 0.0f, infinity, red},
        {glm::vec3(-1.0f, 0.0f, 0.0f), 1e-25f, 1e25f, red},
        {glm::vec3(0.0f, 1.0f, 0.0f), 0.3f, 1.0f / 0.3f, {nan, nan, nan, nan}},
        {glm::vec3(nan, 0.0f, 0.0f), 0.3f, 1.0f / 0.3f, red}};
    const std::vector<render::LineVertex> lines{{{0.0f, 0.0f, 0.0f}, red},     {{nan, 0.0f, 0.0f}, red},
                                                {{infinity, 1.0f, 0.0f}, red}, {{0.0f, -1.0f, 0.0f}, red},
                                                {{0.2f, 0.2f, 1.0f}, red},     {{0.2f, 0.2f, 1.0f}, red}};
    const render::Camera camera = towardOrigin({0.0, 0.0, 5.0}, 1.0, 20.0);
    render::RasterImage image;
    render::rasterise({spheres, {}, lines}, render::rasterView(camera, kWidth, kHeight), {0.0f, 0.0f, 0.0f, 1.0f},
                      image, 2);
    EXPECT_LT(image.depthAt(kWidth / 2, kHeight / 2), 1.0f) << "the valid sphere at the centre";
}

// A cloud of spheres with paths through and past it, some segments across the near plane and some beyond the far
// one: the processor's frame and OpenGL's (every sphere at its exact depth) are the same picture but for
// kProcessorMaxDifferingShare of the pixels (line ends and silhouettes within rounding), whatever layout the
// framebuffer is taken to have.
TEST(ProcessorRaster, DrawsThePictureOpenGLDraws) {
    const auto shapes = sphereCrowd(400, 3.0, 0.05, 0.4, 21);
    const Eigen::AlignedBox3d bounds = boundsOf(shapes);
    const render::Anchor anchor{bounds.center()};
    const render::Camera camera = lookingAt(bounds.center(), Eigen::Vector3d(0.3, 0.5, 1.0), 12.0, 40.0, bounds);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    render::LineBatch lines(anchor);
    for (int k = 0; k < 300; ++k) {
        const Point a(4.5 * unit(rng), 3.0 * unit(rng), 1.5 * unit(rng));
        const Point b = a + Point(2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng));
        const float shade = 0.5f + 0.5f * static_cast<float>(unit(rng));
        lines.add(a, b, {1.0f, shade, 0.0f, 1.0f}, {0.0f, shade, 1.0f, 1.0f});
    }
    // Across the near plane in view, from behind the eye, and out past the far plane.
    const Point eye(camera.eye.x, camera.eye.y, camera.eye.z);
    const Eigen::Vector3d forward = (bounds.center() - eye).normalized();
    const Eigen::Vector3d right = forward.cross(Eigen::Vector3d(0.0, 1.0, 0.0)).normalized();
    const Eigen::Vector3d up = right.cross(forward);
    lines.add(eye + camera.nearPlane * (0.3 * forward + 0.05 * right + 0.03 * up),
              bounds.center() + 0.7 * right + 0.3 * up, test::kLineColour);
    lines.add(eye - 2.0 * forward + 0.2 * right - 0.15 * up, bounds.center() - 0.4 * right + 0.5 * up,
              test::kLineColour);
    lines.add(bounds.center(), bounds.center() + 200.0 * (bounds.center() - eye), test::kLineColour);
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);

    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image drawnByOpenGL = renderer.draw(camera, anchor, instances, lines);
    ASSERT_FALSE(renderer.lastFrameOnProcessor());
    renderer.setProcessorRaster(true);
    const snapshot::Image drawnOnProcessor = renderer.draw(camera, anchor, instances, lines);
    ASSERT_TRUE(renderer.lastFrameOnProcessor());
    EXPECT_GT(test::coveredPixels(drawnByOpenGL), kWidth * kHeight / 3);
    const test::ImageDifference difference =
        test::compareImages(drawnByOpenGL, drawnOnProcessor, test::kGoldenChannelTolerance);
    EXPECT_TRUE(difference.within(test::kProcessorMaxDifferingShare))
        << difference.differingPixels << " of " << difference.pixels << " pixels differ";
    // The window taken to lie in memory otherwise than OSMesa's does (the top row first, RGBA) makes the hand-over
    // slower, never another picture.
    for (const render::PixelLayout layout : test::kEveryLayout) {
        SCOPED_TRACE(test::layoutName(layout));
        renderer.setWindowLayout(layout);
        EXPECT_EQ(renderer.draw(camera, anchor, instances, lines).rgba, drawnOnProcessor.rgba);
        EXPECT_TRUE(renderer.lastFrameOnProcessor());
    }
}

// A picture held for the kept view (Renderer::draw's `hold`) is shown again as drawn, whichever layout the window
// is taken to have, BGRA included; shown into a window taken to have another layout than the one it was drawn in,
// it is declined (its rows and bytes would lie wrongly), and a new draw is needed; a frame not held, drawn in another
// layout in between, changes none of that.
TEST(ProcessorRaster, AHeldPictureIsShownAgainOnlyInTheLayoutItWasDrawnIn) {
    const auto shapes = sphereCrowd(200, 3.0, 0.05, 0.4, 23);
    const Eigen::AlignedBox3d bounds = boundsOf(shapes);
    const render::Anchor anchor{bounds.center()};
    const render::Camera camera = lookingAt(bounds.center(), Eigen::Vector3d(0.3, 0.5, 1.0), 12.0, 40.0, bounds);
    render::LineBatch lines(anchor);
    lines.add(bounds.min(), bounds.max(), {1.0f, 0.5f, 0.0f, 1.0f});
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);
    DirectRenderer renderer(kWidth, kHeight);
    renderer.setProcessorRaster(true);
    renderer.setHold(true);
    for (const render::PixelLayout layout : test::kEveryLayout) {
        SCOPED_TRACE(test::layoutName(layout));
        renderer.setWindowLayout(layout);
        const snapshot::Image drawn = renderer.draw(camera, anchor, instances, lines);
        ASSERT_TRUE(renderer.lastFrameOnProcessor());
        EXPECT_GT(test::coveredPixels(drawn), kWidth * kHeight / 10);
        const std::optional<snapshot::Image> shown = renderer.showHeld();
        ASSERT_TRUE(shown.has_value());
        EXPECT_EQ(shown->rgba, drawn.rgba);
        renderer.setWindowLayout({!layout.topRowFirst, layout.bgra});
        EXPECT_FALSE(renderer.showHeld().has_value()) << "held in another row order";
        renderer.setWindowLayout({layout.topRowFirst, !layout.bgra});
        EXPECT_FALSE(renderer.showHeld().has_value()) << "held in another byte order";
        // A frame drawn since in the other layout, not held, leaves the held picture as it was.
        renderer.setHold(false);
        renderer.draw(camera, anchor, instances, lines);
        renderer.setHold(true);
        renderer.setWindowLayout(layout);
        const std::optional<snapshot::Image> again = renderer.showHeld();
        ASSERT_TRUE(again.has_value());
        EXPECT_EQ(again->rgba, drawn.rgba);
    }
}

// A frame with a box in it is OpenGL's, pixel for pixel; the spheres' colours, rewritten in place for a new
// selection (Renderer::recolourShape), reach the processor's frames too.
TEST(ProcessorRaster, AFrameWithOtherShapesIsOpenGLsAndANewSelectionIsDrawn) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(0.0, 0.0, 0.0), 1.0));
    shapes.push_back(std::make_unique<Box>(Point(1.5, -0.5, -0.5), Point(2.5, 0.5, 0.5)));
    const render::Anchor anchor{Point(0.0, 0.0, 0.0)};
    const render::Camera camera = lookingAt(Point(0.5, 0.0, 0.0), Eigen::Vector3d(0.1, 0.2, 1.0), 8.0, 40.0,
                                            Eigen::AlignedBox3d(Point(-1.0, -1.0, -1.0), Point(2.5, 1.0, 1.0)));
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, anchor);
    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image drawnByOpenGL = renderer.draw(camera, anchor, instances, render::LineBatch(anchor));
    renderer.setProcessorRaster(true);
    const snapshot::Image asked = renderer.draw(camera, anchor, instances, render::LineBatch(anchor));
    EXPECT_FALSE(renderer.lastFrameOnProcessor());
    EXPECT_EQ(test::compareImages(drawnByOpenGL, asked, 0).differingPixels, 0U);

    snapshot::OsmesaContext context(kWidth, kHeight);
    render::Renderer direct(context.gl());
    render::ShapeInstances sphereOnly = instances;
    sphereOnly.boxes.clear();
    sphereOnly.boxIds.clear();
    direct.setShapes(sphereOnly);
    render::RenderOptions options;
    options.processorRaster = true;
    options.background = {0.0f, 0.0f, 0.0f, 1.0f};
    const Eigen::Vector2d middle = test::projectToPixels(camera, Point(0.0, 0.0, 0.0), kWidth, kHeight);
    const auto centrePixel = [&] {
        direct.draw(camera, options, kWidth, kHeight);
        EXPECT_TRUE(direct.lastFrameOnProcessor());
        const snapshot::Image image = context.read();
        const std::uint8_t* rgba = image.pixel(static_cast<int>(middle.x()), static_cast<int>(middle.y()));
        return std::array<int, 3>{rgba[0], rgba[1], rgba[2]};
    };
    direct.draw(camera, options, 3840, 2160);  // kProcessorMostPixels: still the processor's
    EXPECT_TRUE(direct.lastFrameOnProcessor());
    direct.draw(camera, options, 3841, 2160);  // one column more: OpenGL's
    EXPECT_FALSE(direct.lastFrameOnProcessor());
    const std::array<int, 3> before = centrePixel();
    ASSERT_TRUE(direct.recolourShape(instances.roundedIds[0], render::kHighlight));
    const std::array<int, 3> after = centrePixel();
    EXPECT_NE(before, after);
    for (std::size_t channel = 0; channel < 3; ++channel) {  // the centre faces the eye: the full colour
        EXPECT_NEAR(after[channel], 255.0 * render::kHighlight[channel], 1.0) << "channel " << channel;
    }
}

// The renderers the app draws on the processor for: Mesa's on the processor, not a GPU's, even one named after LLVM.
TEST(ProcessorRaster, SoftwareOpenGLsAreKnownByTheirRenderersName) {
    EXPECT_TRUE(render::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(render::isSoftwareRenderer("softpipe"));
    EXPECT_TRUE(render::isSoftwareRenderer("Software Rasterizer"));
    EXPECT_FALSE(render::isSoftwareRenderer("AMD Radeon RX 6800 (navi21, LLVM 15.0.6, DRM 3.49, 6.1.0-13-amd64)"));
    EXPECT_FALSE(render::isSoftwareRenderer("NVIDIA GeForce RTX 3080/PCIe/SSE2"));
    EXPECT_FALSE(render::isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    snapshot::OsmesaContext context(8, 8);
    EXPECT_TRUE(context.gl().isSoftware()) << context.gl().describe();
}

}  // namespace
}  // namespace dropscope
