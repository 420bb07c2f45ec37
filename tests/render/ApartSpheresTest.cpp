// Spheres apart (render/ApartSpheres.hpp): which spheres nothing else drawn reaches into, against a brute-force
// search; and the picture an interactive frame draws with them at their centre's depth, against exact depth.
#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "render/ApartSpheres.hpp"
#include "render/RenderHarness.hpp"
#include "render/SilhouetteCoverage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace dropscope {
namespace {

using render::ApartSpheres;
using test::DirectRenderer;

const render::Anchor kAnchor{Point(0.0, 0.0, 0.0)};

render::ShapeInstance sphere(const Point& centre, double radius) {
    return render::sphereInstance(centre, radius, kAnchor, render::kHighlight);
}

render::LineVertex vertex(const Point& p) { return {kAnchor.relative(p), render::kHighlight}; }

std::vector<std::uint8_t> apartOf(const std::vector<render::ShapeInstance>& spheres,
                                  const std::vector<std::pair<Point, Point>>& segments = {},
                                  const std::vector<render::ShapeInstance>& markers = {},
                                  const std::vector<ApartSpheres::Ball>& otherShapes = {}) {
    ApartSpheres apart;
    apart.setShapes(spheres, otherShapes);
    std::vector<render::LineVertex> vertices;
    for (const auto& [a, b] : segments) {
        vertices.push_back(vertex(a));
        vertices.push_back(vertex(b));
    }
    apart.setSegments(vertices);
    apart.setMarkers(markers);
    return apart.apart();
}

TEST(ApartSpheres, SpheresThatOverlapAreNotApartAndSpheresThatTouchAre) {
    const std::vector<render::ShapeInstance> spheres{
        sphere(Point(0.0, 0.0, 0.0), 1.0),  sphere(Point(1.9, 0.0, 0.0), 1.0),    // overlap by 0.1
        sphere(Point(10.0, 0.0, 0.0), 1.0), sphere(Point(12.0, 0.0, 0.0), 1.0),   // touch
        sphere(Point(30.0, 0.0, 0.0), 2.0), sphere(Point(30.5, 0.0, 0.0), 0.5)};  // one inside the other
    EXPECT_EQ(apartOf(spheres), (std::vector<std::uint8_t>{0, 0, 1, 1, 0, 0}));
}

TEST(ApartSpheres, ASegmentReachingInsideTakesASphereOutButOneEndingOnItsSurfaceDoesNot) {
    const std::vector<render::ShapeInstance> spheres{
        sphere(Point(0.0, 0.0, 0.0), 1.0), sphere(Point(5.0, 0.0, 0.0), 1.0), sphere(Point(10.0, 0.0, 0.0), 1.0),
        sphere(Point(15.0, 0.0, 0.0), 1.0)};
    const Eigen::Vector3d out = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
    const std::vector<std::pair<Point, Point>> segments{
        {Point(-3.0, 0.5, 0.0), Point(3.0, 0.5, 0.0)},                   // through the first
        {Point(5.0, 0.0, 0.0) + out, Point(5.0, 0.0, 0.0) + 4.0 * out},  // from the second's surface outwards
        {Point(7.0, 1.0, 0.0), Point(13.0, 1.0, 0.0)},                   // tangent to the third
        {Point(12.0, 0.99, 0.0), Point(18.0, 0.99, 0.0)}};               // a hundredth of a radius into the fourth
    EXPECT_EQ(apartOf(spheres, segments), (std::vector<std::uint8_t>{0, 1, 1, 0}));
}

TEST(ApartSpheres, MarkersOtherShapesAndEllipsoidsTakeSpheresOut) {
    std::vector<render::ShapeInstance> spheres{sphere(Point(0.0, 0.0, 0.0), 1.0), sphere(Point(5.0, 0.0, 0.0), 1.0),
                                               sphere(Point(10.0, 0.0, 0.0), 1.0), sphere(Point(15.0, 0.0, 0.0), 1.0)};
    const std::vector<render::ShapeInstance> markers{sphere(Point(1.0, 0.0, 0.0), 0.1),   // on the first's surface
                                                     sphere(Point(6.2, 0.0, 0.0), 0.1)};  // clear of the second
    const std::vector<ApartSpheres::Ball> boxes{{glm::vec3(10.0f, 1.5f, 0.0f), 1.0f}};    // a box's bounds
    std::vector<std::unique_ptr<Shape>> ellipsoid;
    ellipsoid.push_back(std::make_unique<Ellipsoid>(
        Ellipsoid::fromSemiAxes(Point(15.0, 0.0, 2.5), Eigen::Vector3d(0.5, 0.5, 2.0), Eigen::Matrix3d::Identity())));
    spheres.push_back(render::buildShapeInstances(ellipsoid, kAnchor).rounded.at(0));
    EXPECT_EQ(apartOf(spheres, {}, markers, boxes), (std::vector<std::uint8_t>{0, 1, 0, 0, 0}));
}

// The grid's answer against every sphere tried with every contact, on clouds laid out to strain the grid: a
// dense cloud with a few large spheres, spheres on a plane, and one sphere much larger than the rest.
TEST(ApartSpheres, TheGridFindsWhatABruteForceSearchFinds) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> share(0.0, 1.0);
    for (int layout = 0; layout < 3; ++layout) {
        SCOPED_TRACE("layout " + std::to_string(layout));
        std::vector<render::ShapeInstance> spheres;
        std::vector<Point> centres;
        std::vector<double> radii;
        for (int k = 0; k < 1500; ++k) {
            const Point c(10.0 * unit(rng), 10.0 * unit(rng), layout == 1 ? 0.0 : 10.0 * unit(rng));
            double r = 0.05 + 0.25 * share(rng);
            if (layout == 0 && k % 100 == 0) r = 2.0;
            if (layout == 2 && k == 0) r = 8.0;
            spheres.push_back(sphere(c, r));
            centres.push_back(c);
            radii.push_back(r);
        }
        std::vector<std::pair<Point, Point>> segments;
        for (int k = 0; k < 400; ++k) {
            const Point a(12.0 * unit(rng), 12.0 * unit(rng), 12.0 * unit(rng));
            const double length = k % 4 == 0 ? 40.0 : 1.5 * share(rng);
            segments.push_back({a, a + length * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized()});
        }
        segments.push_back({Point(-50.0, 0.3, 0.2), Point(50.0, 0.3, 0.2)});  // along an axis, far beyond the grid
        segments.push_back({Point(0.1, -50.0, 0.0), Point(0.1, 50.0, 0.0)});  // in the plane of layout 1
        segments.push_back({Point(3.0, 3.0, 3.0), Point(3.0, 3.0, 3.0)});     // a point
        std::vector<render::ShapeInstance> markers;
        for (int k = 0; k < 200; ++k) {
            markers.push_back(sphere(Point(10.0 * unit(rng), 10.0 * unit(rng), 10.0 * unit(rng)), 0.2 * share(rng)));
        }
        const std::vector<std::uint8_t> grid = apartOf(spheres, segments, markers);

        const auto instanceCentre = [&](std::size_t i) {
            return glm::vec3(spheres[i].center[0], spheres[i].center[1], spheres[i].center[2]);
        };
        const auto instanceRadius = [&](const render::ShapeInstance& s) {
            return glm::length(glm::vec3(s.linear[0], s.linear[1], s.linear[2]));
        };
        int apartCount = 0;
        for (std::size_t i = 0; i < spheres.size(); ++i) {
            const glm::vec3 c = instanceCentre(i);
            const float r = instanceRadius(spheres[i]);
            bool apart = true;
            for (std::size_t j = 0; j < spheres.size() && apart; ++j) {
                if (j == i) continue;
                const float reach = (r + instanceRadius(spheres[j])) * (1.0f - render::kApartReach);
                const glm::vec3 off = instanceCentre(j) - c;
                apart = glm::dot(off, off) >= reach * reach;
            }
            for (const render::ShapeInstance& m : markers) {
                const float reach = (r + instanceRadius(m)) * (1.0f - render::kApartReach);
                const glm::vec3 off = glm::vec3(m.center[0], m.center[1], m.center[2]) - c;
                apart = apart && glm::dot(off, off) >= reach * reach;
            }
            for (const auto& [pa, pb] : segments) {
                const glm::vec3 a(kAnchor.relative(pa)[0], kAnchor.relative(pa)[1], kAnchor.relative(pa)[2]);
                const glm::vec3 b(kAnchor.relative(pb)[0], kAnchor.relative(pb)[1], kAnchor.relative(pb)[2]);
                const glm::vec3 ab = b - a;
                const float length2 = glm::dot(ab, ab);
                const float t = length2 > 0.0f ? std::clamp(glm::dot(c - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
                const glm::vec3 off = a + t * ab - c;
                const float reach = r * (1.0f - render::kApartReach);
                apart = apart && glm::dot(off, off) >= reach * reach;
            }
            ASSERT_EQ(grid[i], apart ? 1 : 0)
                << "sphere " << i << " at " << centres[i].transpose() << " radius " << radii[i];
            apartCount += apart ? 1 : 0;
        }
        // Both answers occur often: the comparison means something.
        EXPECT_GT(apartCount, 100);
        EXPECT_LT(apartCount, 1400);
    }
}

// Droplets 10-30 pixels wide with everything else drawn around them: paths from one droplet's surface to
// another's, lines passing in front and behind, a cell's edge through one droplet and a marker on another. With
// the spheres apart drawn as points at their centre's depth the picture is the exact one but within a pixel of a
// silhouette.
TEST(ApartSpherePicture, LinesAndMarkersShowAsWithExactDepthButAtTheRims) {
    constexpr int kWidth = 320;
    constexpr int kHeight = 240;
    std::vector<std::unique_ptr<Shape>> shapes;
    std::vector<Point> centres;
    std::vector<double> radii;
    for (int k = 0; k < 8; ++k) {
        const Point c(-3.5 + k, 0.6 * std::sin(1.7 * k), 0.8 * std::cos(1.3 * k));
        const double r = 0.2 + 0.04 * k;
        shapes.push_back(std::make_unique<Sphere>(c, r));
        centres.push_back(c);
        radii.push_back(r);
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    bounds.extend(Point(-5.0, -2.0, -3.0));
    bounds.extend(Point(5.0, 2.0, 3.0));
    const Point eye(1.0, 2.0, 16.0);
    const render::Camera camera = test::cameraLookingAt(eye, Point(0.0, 0.0, 0.0), 30.0, bounds);
    render::LineBatch lines(kAnchor);
    const render::Colour green = test::kLineColour;
    const auto onSurface = [&](int k, const Eigen::Vector3d& towards) {
        return Point(centres[static_cast<std::size_t>(k)] + radii[static_cast<std::size_t>(k)] * towards.normalized());
    };
    // Paths between droplets, leaving and entering each on the sides facing one another and the eye.
    for (int k = 0; k + 1 < 8; ++k) {
        const Eigen::Vector3d across = centres[static_cast<std::size_t>(k + 1)] - centres[static_cast<std::size_t>(k)];
        const Eigen::Vector3d toEye = (eye - centres[static_cast<std::size_t>(k)]).normalized();
        lines.add(onSurface(k, across.normalized() + 0.8 * toEye), onSurface(k + 1, -across.normalized() + 0.8 * toEye),
                  green);
    }
    // Outward from droplets' fronts and sides, as a path leaving towards the eye does.
    for (int k = 0; k < 8; k += 2) {
        const Point from = onSurface(k, Eigen::Vector3d(0.3, -1.0, 0.6));
        lines.add(from, from + Eigen::Vector3d(0.3, -1.0, 0.6).normalized() * 1.5, green);
    }
    // In front of one droplet and behind another, by a fifth of their radius.
    lines.add(centres[2] + Eigen::Vector3d(-1.0, 0.0, 1.2 * radii[2]),
              centres[2] + Eigen::Vector3d(1.0, 0.1, 1.2 * radii[2]), green);
    lines.add(centres[5] + Eigen::Vector3d(-1.0, 0.0, -1.2 * radii[5]),
              centres[5] + Eigen::Vector3d(1.0, 0.1, -1.2 * radii[5]), green);
    // A cell's edge through droplet 3, in front of its centre.
    lines.add(centres[3] + Eigen::Vector3d(0.0, -2.0, 0.5 * radii[3]),
              centres[3] + Eigen::Vector3d(0.0, 2.0, 0.5 * radii[3]), green);
    // A marker on droplet 6's back: hidden by it but at the rim.
    const std::vector<render::ShapeInstance> markers{render::sphereInstance(
        onSurface(6, Eigen::Vector3d(0.2, 0.3, -1.0)), 0.6 * radii[6], kAnchor, render::kHighlight)};

    const render::ShapeInstances instances = render::buildShapeInstances(shapes, kAnchor);
    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image exact = renderer.draw(camera, kAnchor, instances, lines, markers);
    renderer.setPointPixels(6.0f);
    const snapshot::Image apart = renderer.draw(camera, kAnchor, instances, lines, markers);

    // The droplets span the widths drawn as points at their centre's depth.
    for (std::size_t k = 0; k < centres.size(); ++k) {
        const double pixels =
            2.0 * radii[k] / (eye - centres[k]).norm() * 0.5 * kHeight / std::tan(camera.fovDeg * M_PI / 360.0);
        EXPECT_GT(pixels, 8.0) << "droplet " << k;
        EXPECT_LT(pixels, 30.0) << "droplet " << k;
    }
    const test::ExactCoverage coverage(shapes, camera, kWidth, kHeight);
    int linePixels = 0;
    int differing = 0;
    int offRim = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            linePixels += test::isLineColour(exact, x, y) ? 1 : 0;
            if (test::samePixel(apart, x, y, exact.pixel(x, y))) continue;
            ++differing;
            if (!coverage.onBoundary(x, y)) {
                ++offRim;
                if (offRim <= 5) ADD_FAILURE() << "pixel (" << x << ", " << y << ") differs away from every rim";
            }
        }
    }
    EXPECT_EQ(offRim, 0) << differing << " pixels differ";
    EXPECT_GT(linePixels, 300);
}

}  // namespace
}  // namespace dropscope
