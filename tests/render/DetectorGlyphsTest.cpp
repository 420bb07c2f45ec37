// Detector glyphs (render/DetectorGlyphs.hpp) as data, no GL: where a plane's outline, axes and arrows go,
// its hatching, fill and image cells and their colours; the far-field frustum; and, drawn by OSMesa, a plane's
// image from traced photons in the snapshot.
#include "render/Colour.hpp"
#include "render/Layers.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/Snapshot.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope {
namespace {

using render::Colour;
using render::LineBatch;
using render::LineVertex;
using render::TriangleBatch;

const std::string kDetectorScene = std::string(DROPSCOPE_TEST_DATA_DIR) + "/scenes/detectors.json";
const Eigen::AlignedBox3d kBounds(Point(-1, -1, -1), Point(1, 1, 1));
constexpr double kSize = 0.5;
constexpr std::size_t kArrowVertices = 6;      // shaft and two barbs
constexpr std::size_t kPlaneVertices = 8 + 4;  // outline and the two half-axes

Point worldOf(const LineVertex& vertex) { return Point(vertex.position[0], vertex.position[1], vertex.position[2]); }

bool sameColour(const Colour& a, const Colour& b) { return a == b; }

Detector plane() {
    Detector detector;
    detector.name = "screen";
    detector.center = Point(0, 0, 5);
    detector.normal = Direction(0, 0, -1);
    detector.size = {4.0, 2.0};
    detector.pixels = {4, 2};
    return detector;
}

struct Glyphs {
    LineBatch lines{render::Anchor{}};
    TriangleBatch surfaces{render::Anchor{}};
};

Glyphs glyphsOf(const std::vector<Detector>& detectors, const std::vector<render::DetectorImage>& images = {}) {
    Glyphs glyphs;
    render::addDetectorGlyphs(glyphs.lines, glyphs.surfaces, detectors, images, kBounds, kSize);
    return glyphs;
}

TEST(DetectorGlyphs, APlaneIsItsOutlineAxesAndAnArrowTowardsTheSideItCounts) {
    Detector front = plane();
    front.side = DetectorSide::Front;
    const Glyphs glyphs = glyphsOf({front});
    ASSERT_EQ(glyphs.lines.vertices().size(), kPlaneVertices + kArrowVertices);
    EXPECT_TRUE(glyphs.surfaces.empty()) << "no image, not absorbing: not filled";
    Eigen::AlignedBox3d outline;
    for (std::size_t k = 0; k < 8; ++k) outline.extend(worldOf(glyphs.lines.vertices()[k]));
    // v is up (y); u = v x n = y x (-z) = -x: the rectangle is 4 wide along x, 2 high along y.
    EXPECT_TRUE(outline.min().isApprox(Point(-2, -1, 5), 1e-6)) << outline.min().transpose();
    EXPECT_TRUE(outline.max().isApprox(Point(2, 1, 5), 1e-6)) << outline.max().transpose();
    const auto& axisU = glyphs.lines.vertices()[9];
    EXPECT_TRUE(worldOf(axisU).isApprox(Point(-2, 0, 5), 1e-6)) << "u's half-axis ends at the edge along u";
    EXPECT_TRUE(sameColour(axisU.colour, render::kDetectorAxisU));
    const Point tip = worldOf(glyphs.lines.vertices()[kPlaneVertices + 1]);
    EXPECT_TRUE(tip.isApprox(Point(0, 0, 5 - kSize), 1e-6)) << "front: the arrow along the normal";

    Detector back = plane();
    back.side = DetectorSide::Back;
    const Point backTip = worldOf(glyphsOf({back}).lines.vertices()[kPlaneVertices + 1]);
    EXPECT_TRUE(backTip.isApprox(Point(0, 0, 5 + kSize), 1e-6)) << "back: the arrow against the normal";
    EXPECT_EQ(glyphsOf({plane()}).lines.vertices().size(), kPlaneVertices + 2 * kArrowVertices) << "both: two arrows";
}

TEST(DetectorGlyphs, AnAbsorbingPlaneIsHatchedAndFilledDarkWithoutAnImage) {
    Detector absorbing = plane();
    absorbing.absorbing = true;
    const Glyphs glyphs = glyphsOf({absorbing});
    EXPECT_GT(glyphs.lines.vertices().size(), kPlaneVertices + 2 * kArrowVertices) << "hatching";
    for (std::size_t k = kPlaneVertices + 2 * kArrowVertices; k < glyphs.lines.vertices().size(); ++k) {
        const Point p = worldOf(glyphs.lines.vertices()[k]);
        EXPECT_LE(std::abs(p.x()), 2.0 + 1e-6);
        EXPECT_LE(std::abs(p.y()), 1.0 + 1e-6) << "a hatch line stays inside the rectangle";
    }
    ASSERT_EQ(glyphs.surfaces.vertices().size(), 6u);
    EXPECT_TRUE(sameColour(glyphs.surfaces.vertices().front().colour, render::kAbsorbingFill));
}

TEST(DetectorGlyphs, AnImageIsOneQuadAPixelInViridisNormalisedToItsMaximum) {
    const Detector screen = plane();  // 4 x 2 pixels
    const render::DetectorImage image{"screen", screen.pixels, {0, 0, 0, 0, 0, 0, 0, 0.5}};
    const Glyphs glyphs = glyphsOf({screen}, {image});
    ASSERT_EQ(glyphs.surfaces.vertices().size(), 6u * 8u);
    // Pixel (0, 0) is the corner at -u, -v: x = +2 (u is -x), y = -1; pixel (3, 1), the brightest, at +u, +v.
    const auto cellOf = [&](std::size_t pixel) {
        Eigen::AlignedBox3d box;
        for (std::size_t k = 0; k < 6; ++k) box.extend(worldOf(glyphs.surfaces.vertices()[6 * pixel + k]));
        return box;
    };
    EXPECT_TRUE(cellOf(0).isApprox(Eigen::AlignedBox3d(Point(1, -1, 5), Point(2, 0, 5)), 1e-6));
    EXPECT_TRUE(cellOf(7).isApprox(Eigen::AlignedBox3d(Point(-2, 0, 5), Point(-1, 1, 5)), 1e-6));
    EXPECT_TRUE(sameColour(glyphs.surfaces.vertices()[0].colour, render::viridis(0.0)));
    EXPECT_TRUE(sameColour(glyphs.surfaces.vertices()[6 * 7].colour, render::viridis(1.0)));

    const render::DetectorImage otherGrid{"screen", {2, 2}, {1, 1, 1, 1}};
    EXPECT_TRUE(glyphsOf({screen}, {otherGrid}).surfaces.empty()) << "an image of another grid is not drawn";
    const render::DetectorImage otherName{"wall", screen.pixels, std::vector<double>(8, 1.0)};
    EXPECT_TRUE(glyphsOf({screen}, {otherName}).surfaces.empty());
}

TEST(DetectorGlyphs, ALargeImageIsSummedInBlocks) {
    Detector screen = plane();
    screen.pixels = {2 * render::kMaxDrawnImageSide, 3};
    render::DetectorImage image{"screen", screen.pixels, std::vector<double>(screen.pixels.count(), 0.0)};
    image.values[screen.pixels.index(1, 0)] = 1.0;  // the block of pixels 0 and 1
    const Glyphs glyphs = glyphsOf({screen}, {image});
    ASSERT_EQ(glyphs.surfaces.vertices().size(), 6u * render::kMaxDrawnImageSide * 3u);
    EXPECT_TRUE(sameColour(glyphs.surfaces.vertices()[0].colour, render::viridis(1.0)));
    EXPECT_TRUE(sameColour(glyphs.surfaces.vertices()[6].colour, render::viridis(0.0)));
}

TEST(DetectorGlyphs, AFarFieldCameraIsAFrustumOutsideTheSceneLookingAlongItsLook) {
    Detector sky;
    sky.name = "sky";
    sky.type = DetectorType::FarField;
    sky.look = Direction(0, 0, 1);
    sky.fovDeg = 90.0;
    sky.pixels = {64, 32};
    Detector absorbed;
    absorbed.name = "absorbed";
    absorbed.type = DetectorType::ShapeAbsorption;
    const Glyphs glyphs = glyphsOf({sky, absorbed});
    ASSERT_EQ(glyphs.lines.vertices().size(), 16u + 4u) << "4 edges from the eye, 4 of the far end, the up tick";
    const Point eye = render::farFieldGlyphEye(sky, kBounds, kSize);
    EXPECT_TRUE(eye.isApprox(Point(0, 0, -std::sqrt(3.0) - kSize), 1e-9)) << "on the side it looks from";
    EXPECT_TRUE(worldOf(glyphs.lines.vertices()[0]).isApprox(eye, 1e-6));
    Eigen::AlignedBox3d end;
    for (std::size_t k = 0; k < 16; k += 2) end.extend(worldOf(glyphs.lines.vertices()[k + 1]));
    // 90 degrees across: the far end, kSize from the eye, is 2 kSize wide and half as high (64 x 32 pixels).
    EXPECT_NEAR(end.sizes().x(), 2.0 * kSize, 1e-6);
    EXPECT_NEAR(end.sizes().y(), kSize, 1e-6);
    EXPECT_NEAR(end.min().z(), eye.z() + kSize, 1e-6);
    const Eigen::AlignedBox3d grown = render::withDetectorGlyphs(kBounds, {sky, absorbed}, kBounds, kSize);
    EXPECT_TRUE(grown.contains(eye));
}

TEST(DetectorGlyphs, PlaneImagesComeFromTheRunsDetectorTables) {
    const Scene scene = loadScene(kDetectorScene);
    const OpticalScene optical(scene);
    TallySet tallies;
    addDetectorTallies(tallies, scene, PolarisationModel::None);
    TraceSettings settings;
    settings.photons = 2000;
    settings.transport.polarisation = PolarisationModel::None;
    const TraceResult result = runTrace(optical, scene.sources, settings, tallies);
    ResultReport report;
    result.tallies.report(report);
    const std::vector<render::DetectorImage> images = render::planeDetectorImages(report, scene.detectors);
    ASSERT_EQ(images.size(), 2u) << "the two planes; not the far-field camera or the absorption";
    EXPECT_EQ(images[0].name, "screen");
    EXPECT_EQ(images[0].values.size(), 48u * 48u);
    double total = 0.0;
    for (double value : images[0].values) total += value;
    EXPECT_GT(total, 0.5) << "most of the light crosses the screen";
    EXPECT_LE(total, 1.0 + 1e-12);
}

// Drawn: seen from behind the screen, its image covers the view; without photons it is an outline only.
TEST(DetectorGlyphs, TheSnapshotDrawsAPlanesImageFromItsPhotons) {
    const Scene scene = loadScene(kDetectorScene);
    snapshot::SnapshotOptions options;
    options.width = 80;
    options.height = 60;
    options.eye = Point(0, 0, 12);
    options.target = Point(0, 0, 5);
    options.layers.detectors = true;
    const snapshot::Image outline = snapshot::renderSnapshot(scene, options);
    options.photons = 3000;
    const snapshot::Image image = snapshot::renderSnapshot(scene, options);
    const int x = 8;  // between the outline and the droplet
    const int y = 8;
    EXPECT_TRUE(std::equal(outline.pixel(x, y), outline.pixel(x, y) + 3, outline.pixel(70, 2)))
        << "no image: the background there";
    EXPECT_FALSE(std::equal(image.pixel(x, y), image.pixel(x, y) + 3, outline.pixel(x, y))) << "the image";
    // The image's dim corner is viridis' dark violet: blue above green.
    EXPECT_GT(image.pixel(x, y)[2], image.pixel(x, y)[1]);
}

}  // namespace
}  // namespace dropscope
