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
                                  const std::vector<ApartSpheres::Ball>& otherShapes = {},
                                  const std::vector<Point>& triangles = {}) {
    ApartSpheres apart;
    apart.setShapes(spheres, otherShapes);
    std::vector<render::LineVertex> vertices;
    for (const auto& [a, b] : segments) {
        vertices.push_back(vertex(a));
        vertices.push_back(vertex(b));
    }
    apart.setSegments(vertices);
    apart.setMarkers(markers);
    std::vector<render::LineVertex> corners;
    for (const Point& p : triangles) corners.push_back(vertex(p));
    apart.setTriangles(corners);
    return apart.apart();
}

glm::vec3 asVec(const std::array<float, 3>& p) { return {p[0], p[1], p[2]}; }

// The distance from p to triangle abc another way than ApartSpheres': to its plane where p's foot lies inside
// (all three edge normals agree), else to the nearest edge.
float distanceToTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const auto toSegment = [&](const glm::vec3& u, const glm::vec3& v) {
        const glm::vec3 uv = v - u;
        const float length2 = glm::dot(uv, uv);
        const float t = length2 > 0.0f ? std::clamp(glm::dot(p - u, uv) / length2, 0.0f, 1.0f) : 0.0f;
        return glm::length(u + t * uv - p);
    };
    const float edges = std::min({toSegment(a, b), toSegment(b, c), toSegment(c, a)});
    const glm::vec3 normal = glm::cross(b - a, c - a);
    if (glm::dot(normal, normal) == 0.0f) return edges;
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 foot = p - glm::dot(p - a, n) * n;
    const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0.0f &&
                        glm::dot(glm::cross(c - b, foot - b), n) >= 0.0f &&
                        glm::dot(glm::cross(a - c, foot - c), n) >= 0.0f;
    return inside ? std::abs(glm::dot(p - a, n)) : edges;
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
// dense cloud with a few large spheres, spheres on a plane, and one sphere much larger than the rest; with
// ellipsoids, boxes' bounding balls, markers, triangles and segments long and short.
TEST(ApartSpheres, TheGridFindsWhatABruteForceSearchFinds) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> share(0.0, 1.0);
    const auto randomPoint = [&](double half) { return Point(half * unit(rng), half * unit(rng), half * unit(rng)); };
    for (int layout = 0; layout < 3; ++layout) {
        SCOPED_TRACE("layout " + std::to_string(layout));
        std::vector<render::ShapeInstance> rounded;
        for (int k = 0; k < 1500; ++k) {
            const Point c(10.0 * unit(rng), 10.0 * unit(rng), layout == 1 ? 0.0 : 10.0 * unit(rng));
            double r = 0.05 + 0.25 * share(rng);
            if (layout == 0 && k % 100 == 0) r = 2.0;
            if (layout == 2 && k == 0) r = 8.0;
            rounded.push_back(sphere(c, r));
        }
        std::vector<std::unique_ptr<Shape>> ellipsoids;
        for (int k = 0; k < 20; ++k) {
            ellipsoids.push_back(std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(
                randomPoint(10.0), Eigen::Vector3d(0.1, 0.2, 0.6), Eigen::Matrix3d::Identity())));
        }
        for (const render::ShapeInstance& e : render::buildShapeInstances(ellipsoids, kAnchor).rounded) {
            rounded.push_back(e);
        }
        std::vector<ApartSpheres::Ball> boxes;
        for (int k = 0; k < 20; ++k) {
            const Point c = randomPoint(10.0);
            boxes.push_back({glm::vec3(asVec(kAnchor.relative(c))), static_cast<float>(0.5 * share(rng))});
        }
        std::vector<std::pair<Point, Point>> segments;
        for (int k = 0; k < 400; ++k) {
            const Point a = randomPoint(12.0);
            const double length = k % 4 == 0 ? 40.0 : 1.5 * share(rng);
            segments.push_back({a, a + length * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized()});
        }
        segments.push_back({Point(-50.0, 0.3, 0.2), Point(50.0, 0.3, 0.2)});  // along an axis, far beyond the grid
        segments.push_back({Point(0.1, -50.0, 0.0), Point(0.1, 50.0, 0.0)});  // in the plane of layout 1
        segments.push_back({Point(3.0, 3.0, 3.0), Point(3.0, 3.0, 3.0)});     // a point
        std::vector<render::ShapeInstance> markers;
        for (int k = 0; k < 200; ++k) markers.push_back(sphere(randomPoint(10.0), 0.2 * share(rng)));
        std::vector<Point> triangles;
        for (int k = 0; k < 30; ++k) {
            const Point a = randomPoint(10.0);
            triangles.push_back(a);
            triangles.push_back(a + 3.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
            triangles.push_back(a + 3.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
        }
        triangles.insert(triangles.end(),
                         {Point(1.0, 1.0, 1.0), Point(2.0, 2.0, 2.0), Point(4.0, 4.0, 4.0)});  // no area

        const std::vector<std::uint8_t> grid = apartOf(rounded, segments, markers, boxes, triangles);
        // Every other thing as a ball (shapes' bounds, markers), then the segments and triangles.
        std::vector<ApartSpheres::Ball> balls = boxes;
        for (const auto& r : rounded) balls.push_back(ApartSpheres::boundingBall(r));
        for (const auto& m : markers) balls.push_back(ApartSpheres::boundingBall(m));
        int apartCount = 0;
        for (std::size_t i = 0; i < rounded.size(); ++i) {
            const ApartSpheres::Ball s = ApartSpheres::boundingBall(rounded[i]);
            bool apart = render::isSphereInstance(rounded[i]);
            for (std::size_t j = 0; j < balls.size() && apart; ++j) {
                if (j == boxes.size() + i) continue;  // itself
                const float reach =
                    s.radius + balls[j].radius - render::kApartReach * std::min(s.radius, balls[j].radius);
                apart = glm::length(balls[j].centre - s.centre) >= reach;
            }
            const float deep = s.radius * (1.0f - render::kApartReach);
            for (const auto& [pa, pb] : segments) {
                const glm::vec3 a = asVec(kAnchor.relative(pa));
                const glm::vec3 ab = asVec(kAnchor.relative(pb)) - a;
                const float length2 = glm::dot(ab, ab);
                const float t = length2 > 0.0f ? std::clamp(glm::dot(s.centre - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
                apart = apart && glm::length(a + t * ab - s.centre) >= deep;
            }
            for (std::size_t k = 0; k < triangles.size(); k += 3) {
                apart = apart && distanceToTriangle(s.centre, asVec(kAnchor.relative(triangles[k])),
                                                    asVec(kAnchor.relative(triangles[k + 1])),
                                                    asVec(kAnchor.relative(triangles[k + 2]))) >= deep;
            }
            ASSERT_EQ(grid[i], apart ? 1 : 0) << "shape " << i << " at " << s.centre.x << " " << s.centre.y << " "
                                              << s.centre.z << " radius " << s.radius;
            apartCount += apart ? 1 : 0;
        }
        // Both answers occur often: the comparison means something.
        EXPECT_GT(apartCount, 100);
        EXPECT_LT(apartCount, 1400);
    }
}

// Anything not finite (a coordinate beyond float, once anchor-relative) leaves no sphere apart, and a cloud packed
// into a few cells of a wide grid is answered within the work budget, never with a sphere apart that is not.
TEST(ApartSpheres, NothingNotFiniteAndNoCrowdingHangsOrMisleads) {
    const std::vector<render::ShapeInstance> two{sphere(Point(0.0, 0.0, 0.0), 1.0), sphere(Point(5.0, 0.0, 0.0), 1.0)};
    EXPECT_EQ(apartOf(two), (std::vector<std::uint8_t>{1, 1}));
    const double huge = 1e300;  // beyond float: infinite once relative to the anchor
    std::vector<render::ShapeInstance> withInfinite = two;
    withInfinite.push_back(sphere(Point(huge, 0.0, 0.0), 1.0));
    EXPECT_EQ(apartOf(withInfinite), (std::vector<std::uint8_t>{0, 0, 0}));
    EXPECT_EQ(apartOf(two, {{Point(10.0, 0.0, 0.0), Point(huge, 0.0, 0.0)}}), (std::vector<std::uint8_t>{0, 0}));
    EXPECT_EQ(apartOf(two, {}, {sphere(Point(-huge, 0.0, 0.0), 1.0)}), (std::vector<std::uint8_t>{0, 0}));
    EXPECT_EQ(apartOf(two, {}, {}, {}, {Point(9.0, 0.0, 0.0), Point(9.0, 1.0, 0.0), Point(huge, 0.0, 0.0)}),
              (std::vector<std::uint8_t>{0, 0}));
    std::vector<render::ShapeInstance> extremes{sphere(Point(-3e38, 0.0, 0.0), 1.0),
                                                sphere(Point(3e38, 0.0, 0.0), 1.0)};
    EXPECT_EQ(apartOf(extremes), (std::vector<std::uint8_t>{1, 1}));  // an extent beyond float, not beyond double

    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<render::ShapeInstance> crowded;
    for (int k = 0; k < 40000; ++k) crowded.push_back(sphere(Point(unit(rng), unit(rng), unit(rng)), 0.004));
    for (int k = 0; k < 20; ++k)
        crowded.push_back(sphere(Point(1e3 * unit(rng), 1e3 * unit(rng), 1e3 * unit(rng)), 0.01));
    const std::vector<std::uint8_t> flags = apartOf(crowded);
    for (std::size_t i = 0; i + 20 < crowded.size(); i += 97) {
        if (flags[i] == 0) continue;
        const glm::vec3 c = asVec(crowded[i].center);
        for (std::size_t j = 0; j < crowded.size(); ++j) {
            if (j != i) {
                ASSERT_GE(glm::length(asVec(crowded[j].center) - c), 0.008f * (1.0f - render::kApartReach));
            }
        }
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
    EXPECT_GE(renderer.apartInLastFrame(), 5U) << "the droplets no line or marker reaches into";

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

// Compares `apart` with `exact` pixel by pixel: any difference must lie within a pixel of a silhouette.
void expectSameButAtTheRims(const snapshot::Image& exact, const snapshot::Image& apart,
                            const test::ExactCoverage& coverage) {
    int differing = 0;
    int offRim = 0;
    for (int y = 0; y < exact.height; ++y) {
        for (int x = 0; x < exact.width; ++x) {
            if (test::samePixel(apart, x, y, exact.pixel(x, y))) continue;
            ++differing;
            if (!coverage.onBoundary(x, y) && ++offRim <= 5) {
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") differs away from every rim";
            }
        }
    }
    EXPECT_EQ(offRim, 0) << differing << " pixels differ";
}

// 135 droplets 10-16 pixels wide, none reaching into another, from the view's centre out to its corners (where
// the centre's depth strays furthest from the sphere's span: impostor.vert keeps such droplets to exact depth),
// with segments square to a radius of each droplet just beyond its surface in many directions, so that lines pass
// just in front of and just behind every rim.
TEST(ApartSpherePicture, TangentLinesAroundDropletsToTheCornersShowAsWithExactDepth) {
    constexpr int kWidth = 400;
    constexpr int kHeight = 250;
    std::mt19937_64 rng(47);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<std::unique_ptr<Shape>> shapes;
    render::LineBatch lines(kAnchor);
    for (int ix = -7; ix <= 7; ++ix) {
        for (int iy = -4; iy <= 4; ++iy) {
            const Point c(1.0 * ix + 0.05 * unit(rng), 1.0 * iy + 0.05 * unit(rng), 1.5 * unit(rng));
            const double r = 0.25 + 0.07 * (1.0 + unit(rng));
            shapes.push_back(std::make_unique<Sphere>(c, r));
            for (int k = 0; k < 4; ++k) {
                // Square to a radius, a sixth of a radius beyond the surface: nearer, a line and the sphere's
                // exact depth (each rasterised at its own place within a pixel) can disagree which is in front.
                const Eigen::Vector3d out = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
                const Eigen::Vector3d along = out.cross(Eigen::Vector3d(unit(rng), unit(rng), unit(rng))).normalized();
                const Point touch = c + 1.17 * r * out;
                lines.add(touch - 0.2 * along, touch + 0.2 * along, test::kLineColour);
            }
        }
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    const render::Camera camera = test::cameraLookingAt(Point(0.0, 0.0, 11.0), Point(0.0, 0.0, 0.0), 60.0, bounds);
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, kAnchor);
    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image exact = renderer.draw(camera, kAnchor, instances, lines);
    renderer.setPointPixels(6.0f);
    const snapshot::Image apart = renderer.draw(camera, kAnchor, instances, lines);
    EXPECT_GT(renderer.apartInLastFrame(), instances.rounded.size() / 2);
    expectSameButAtTheRims(exact, apart, test::ExactCoverage(shapes, camera, kWidth, kHeight));
}

// Off the view's axis the centre's depth lies beyond the sphere's span along the outer R (1 - cos phi) of its
// silhouette. A droplet 27 pixels wide 33 degrees off the axis, with short lines just behind it exactly where
// the span ends before the centre's depth, must hide them: impostor.vert keeps it to exact depth, and
// drawRounded runs the exact points for its chunk.
TEST(ApartSpherePicture, ADropletInTheCornerHidesWhatLiesJustBehindItsRim) {
    constexpr int kWidth = 400;
    constexpr int kHeight = 250;
    const Point eye(0.0, 0.0, 10.0);
    std::vector<std::unique_ptr<Shape>> shapes;
    // About 33 degrees off the axis but well inside a wide view: alone in its chunk, which lies clear of the
    // view's planes (so is not drawn as quads for being near them).
    shapes.push_back(std::make_unique<Sphere>(Point(5.6, 3.2, 0.0), 0.9));
    Eigen::AlignedBox3d bounds(Point(-7.0, -4.5, -6.0), Point(7.0, 4.5, 6.0));  // the planes clear of the chunk
    const render::Camera camera = test::cameraLookingAt(eye, Point(0.0, 0.0, 0.0), 90.0, bounds);
    const Eigen::Vector3d forward(0.0, 0.0, -1.0);
    render::LineBatch lines(kAnchor);
    int behind = 0;
    for (const auto& shape : shapes) {
        const auto& sphere = static_cast<const Sphere&>(*shape);
        const Eigen::Vector2d middle = test::projectToPixels(camera, sphere.center(), kWidth, kHeight);
        const Eigen::Vector3d d = sphere.center() - eye;
        const double centreDepth = d.dot(forward);
        for (int y = static_cast<int>(middle.y()) - 24; y <= static_cast<int>(middle.y()) + 24; y += 2) {
            for (int x = static_cast<int>(middle.x()) - 24; x <= static_cast<int>(middle.x()) + 24; x += 2) {
                const Eigen::Vector3d ray = test::pixelRay(camera, x, y, kWidth, kHeight).vector();
                const double middleT = d.dot(ray);
                const double half2 = sphere.radius() * sphere.radius() - (d - middleT * ray).squaredNorm();
                if (half2 <= 0.0) continue;
                const double exitT = middleT + std::sqrt(half2);
                const double exitDepth = exitT * ray.dot(forward);
                // Where the span ends before the centre's depth (the corner's rim), halfway between the two;
                // elsewhere a tenth of a radius behind the exit.
                const double t = exitDepth < centreDepth ? 0.5 * (exitT + centreDepth / ray.dot(forward))
                                                         : exitT + 0.1 * sphere.radius();
                const Point p = eye + t * ray;
                const Eigen::Vector3d across = ray.cross(d).normalized() * 0.08;  // about 2 pixels, along the rim
                lines.add(p - across, p + across, test::kLineColour);
                behind += exitDepth < centreDepth ? 1 : 0;
            }
        }
    }
    ASSERT_GT(behind, 8) << "the corner droplet's span should end before its centre's depth at some pixels";
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, kAnchor);
    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image exact = renderer.draw(camera, kAnchor, instances, lines);
    renderer.setPointPixels(6.0f);
    const snapshot::Image apart = renderer.draw(camera, kAnchor, instances, lines);
    EXPECT_EQ(renderer.apartInLastFrame(), 1U);
    expectSameButAtTheRims(exact, apart, test::ExactCoverage(shapes, camera, kWidth, kHeight));
}

// Droplets alone, every one apart, in several chunks: the same picture.
TEST(ApartSpherePicture, DropletsAloneInManyChunksLookTheSame) {
    constexpr int kWidth = 320;
    constexpr int kHeight = 240;
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int ix = 0; ix < 20; ++ix) {
        for (int iy = 0; iy < 20; ++iy) {
            shapes.push_back(std::make_unique<Sphere>(Point(0.5 * ix, 0.5 * iy, 0.3 * ((ix * 7 + iy * 3) % 5)),
                                                      0.1 + 0.01 * ((ix + iy) % 9)));
        }
    }
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) bounds.extend(shape->bounds());
    const render::Camera camera = test::cameraLookingAt(Point(5.0, 3.0, 14.0), Point(4.75, 4.75, 0.0), 45.0, bounds);
    const render::ShapeInstances instances = render::buildShapeInstances(shapes, kAnchor);
    DirectRenderer renderer(kWidth, kHeight);
    const snapshot::Image exact = renderer.draw(camera, kAnchor, instances, render::LineBatch(kAnchor));
    renderer.setPointPixels(6.0f);
    const snapshot::Image apart = renderer.draw(camera, kAnchor, instances, render::LineBatch(kAnchor));
    EXPECT_EQ(renderer.apartInLastFrame(), shapes.size());
    EXPECT_GT(test::coveredPixels(exact), 5000);
    expectSameButAtTheRims(exact, apart, test::ExactCoverage(shapes, camera, kWidth, kHeight));
    renderer.setApartSpheres(false);
    renderer.draw(camera, kAnchor, instances, render::LineBatch(kAnchor));
    EXPECT_EQ(renderer.apartInLastFrame(), 0U);
}

}  // namespace
}  // namespace dropscope
