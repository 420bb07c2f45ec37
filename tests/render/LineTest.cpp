// Lines land where the camera math says: an octree root drawn as a wire box, a path segment drawn by the
// renderer directly, and a traced photon's first segment in a real snapshot.
#include "geometry/Sphere.hpp"
#include "render/RenderHarness.hpp"
#include "render/RenderTolerances.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/Snapshot.hpp"
#include "tree/Octree.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace dropscope {
namespace {

using test::DirectRenderer;
using test::kLineReachPixels;

constexpr int kWidth = 160;
constexpr int kHeight = 120;

using Segment2d = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// Points along a projected segment, about every pixel, away from its ends (kSegmentEndShare).
std::vector<Eigen::Vector2d> samplesAlong(const Segment2d& segment, double from = test::kSegmentEndShare,
                                          double to = 1.0 - test::kSegmentEndShare) {
    const auto& [a, b] = segment;
    const int count = std::max(2, static_cast<int>((b - a).norm() * (to - from)));
    std::vector<Eigen::Vector2d> points;
    for (int k = 0; k <= count; ++k) points.push_back(a + (from + (to - from) * k / count) * (b - a));
    return points;
}

Eigen::Vector2d unitNormal(const Segment2d& segment) {
    const Eigen::Vector2d along = (segment.second - segment.first).normalized();
    return {-along.y(), along.x()};
}

render::Camera camera(const Point& eye, const Point& target, const Eigen::AlignedBox3d& bounds) {
    return test::cameraLookingAt(eye, target, 45.0, bounds);
}

// Along the projected segment (samples between the shares `from` and `to` of its length): a lit pixel
// next to every sample, and none a little farther to either side than any pixel of the line can be.
template <class Lit>
void expectLineAlong(const Segment2d& projected, Lit lit, double from = test::kSegmentEndShare,
                     double to = 1.0 - test::kSegmentEndShare) {
    const Eigen::Vector2d normal = unitNormal(projected);
    const double clear = test::kLineDistancePixels + kLineReachPixels + 1.5;
    for (const Eigen::Vector2d& point : samplesAlong(projected, from, to)) {
        EXPECT_TRUE(test::litNear(point, kLineReachPixels, lit)) << "unlit at " << point.transpose();
        for (const double side : {-clear, clear}) {
            const Eigen::Vector2d off = point + side * normal;
            EXPECT_FALSE(lit(static_cast<int>(std::floor(off.x())), static_cast<int>(std::floor(off.y()))))
                << "lit off the segment at " << off.transpose();
        }
    }
}

// The octree of three droplets; its root cell drawn as a wire box by LineBatch::addBox. Each corner has a
// lit pixel next to where Camera::project puts it, every edge is lit along its projection, and no pixel
// is lit away from the projected edges.
TEST(LineGeometry, OctreeRootBoxProjectsItsCornersWhereTheCameraSays) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Point(10.0, 20.0, 30.0), 0.5));
    shapes.push_back(std::make_unique<Sphere>(Point(11.5, 20.4, 29.0), 0.3));
    shapes.push_back(std::make_unique<Sphere>(Point(9.2, 21.0, 30.8), 0.4));
    const Octree octree(std::move(shapes));
    const Eigen::AlignedBox3d root = octree.rootBounds();
    const Point from = root.center() + 1.6 * root.diagonal().norm() * Point(3.0, 2.2, 4.5).normalized();
    const render::Camera view = camera(from, root.center(), root);
    const render::Anchor anchor{root.center()};
    render::LineBatch lines(anchor);
    lines.addBox(root, test::kLineColour);

    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image image = renderer.draw(view, anchor, {}, lines);
    const auto lit = [&](int x, int y) { return test::inImage(image, x, y) && test::isLineColour(image, x, y); };

    std::array<Eigen::Vector2d, 8> corners;
    for (int i = 0; i < 8; ++i) {
        corners[static_cast<std::size_t>(i)] =
            test::projectToPixels(view, root.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)), kWidth, kHeight);
        const Eigen::Vector2d& corner = corners[static_cast<std::size_t>(i)];
        ASSERT_TRUE(test::insideImage(corner, kWidth, kHeight, 4.0)) << "corner " << i << " at " << corner.transpose();
        EXPECT_TRUE(test::litNear(corner, kLineReachPixels, lit))
            << "no line pixel at corner " << i << ", projected to " << corner.transpose();
    }
    std::vector<Segment2d> edges;  // corner i has bit 0 = x max, bit 1 = y max, bit 2 = z max
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit))
                edges.emplace_back(corners[static_cast<std::size_t>(i)], corners[static_cast<std::size_t>(i | bit)]);
        }
    }
    for (std::size_t e = 0; e < edges.size(); ++e) {
        for (const Eigen::Vector2d& point : samplesAlong(edges[e])) {
            EXPECT_TRUE(test::litNear(point, kLineReachPixels, lit))
                << "edge " << e << " unlit at " << point.transpose();
        }
    }
    int litPixels = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!lit(x, y)) {
                EXPECT_TRUE(test::isBlack(image, x, y))
                    << "pixel (" << x << ", " << y << ") neither line nor background";
                continue;
            }
            ++litPixels;
            double nearest = 1e300;
            for (const Segment2d& edge : edges) {
                nearest = std::min(nearest, test::distanceToSegment({x + 0.5, y + 0.5}, edge.first, edge.second));
            }
            EXPECT_LE(nearest, test::kLineDistancePixels)
                << "pixel (" << x << ", " << y << ") lit away from every edge";
        }
    }
    EXPECT_GT(litPixels, 100);
}

// One oblique segment far from the origin: lit along its projection, background a few pixels to either
// side.
TEST(LineGeometry, PathSegmentCrossesTheExpectedPixels) {
    const Point a(-101.2, 48.9, 7.5);
    const Point b(-98.4, 50.6, 5.1);
    const Eigen::AlignedBox3d bounds(a.cwiseMin(b), a.cwiseMax(b));
    const render::Camera view = camera(bounds.center() + Point(-0.8, 1.1, 4.0), bounds.center(), bounds);
    const render::Anchor anchor{bounds.center()};
    render::LineBatch lines(anchor);
    lines.add(a, b, test::kLineColour);

    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image image = renderer.draw(view, anchor, {}, lines);
    const auto lit = [&](int x, int y) { return test::inImage(image, x, y) && test::isLineColour(image, x, y); };
    const Segment2d projected{test::projectToPixels(view, a, kWidth, kHeight),
                              test::projectToPixels(view, b, kWidth, kHeight)};
    ASSERT_GT((projected.second - projected.first).norm(), 60.0) << "the segment should cross a good part of the image";
    expectLineAlong(projected, lit);
}

// The real snapshot (scene view, anchor, trace, path layer): a ray source's photon travels from the
// source to the droplet first, and that segment is drawn where the scene's view projects it.
TEST(LineGeometry, TracedPhotonsFirstSegmentCrossesTheExpectedPixelsOfASnapshot) {
    const Scene scene = parseScene(R"({
      "dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "water": {"n": 1.333}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
      "sources": [{"type": "ray", "origin": [-3, 1.5, 0.5], "direction": [3, -1.2, -0.5]}],
      "view": {"eye": [0, 0, 7.5], "target": [0, 0, 0], "fov_deg": 40}
    })",
                                   "first-segment.json");
    snapshot::SnapshotOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.paths = 1;
    const snapshot::Image image = snapshot::renderSnapshot(scene, options);

    const Source& source = scene.sources.front();
    const double entry = scene.shapes.front()->distanceToSurface(source.origin, source.direction);
    ASSERT_FALSE(std::isnan(entry));
    const render::Camera view = render::Camera::fromView(*scene.view);
    const Segment2d projected{
        test::projectToPixels(view, source.origin, kWidth, kHeight),
        test::projectToPixels(view, source.origin + entry * source.direction.vector(), kWidth, kHeight)};
    const std::uint8_t* background = image.pixel(0, 0);  // the scene leaves the top-left corner empty
    const auto lit = [&](int x, int y) {
        return test::inImage(image, x, y) && !test::samePixel(image, x, y, background);
    };
    // The first 70 % of the segment: its end runs into the droplet's silhouette.
    expectLineAlong(projected, lit, test::kSegmentEndShare, 0.7);
}

}  // namespace
}  // namespace dropscope
