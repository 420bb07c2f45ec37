// --diffraction fraunhofer in the tracer: which photons a droplet diffracts (those through its halo's ring, as many
// as meet it in a plane wave), by how much (the Airy pattern of its outline), and that nothing else changes.
#include "TransportFixtures.hpp"

#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "transport/DropletDiffraction.hpp"
#include "transport/PhotonTracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace dropscope {
namespace {

using testing::monteCarloTolerance;
using testing::sceneFromJson;

// A water drop of radius 0.05 mm at the origin; 532 nm in air: x = 2 pi a / lambda = 590.5.
const Scene& waterDrop() {
    static const Scene scene = sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                                             R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.05,
                                                 "medium": "water"})",
                                             "");
    return scene;
}
constexpr double kRadius = 0.05;
const double kSizeParameter = 2.0 * std::numbers::pi * kRadius / 532e-6;

TransportSettings fraunhofer() {
    TransportSettings settings;
    settings.diffraction = DiffractionModel::Fraunhofer;
    return settings;
}

std::vector<Event> trace(const OpticalScene& scene, double impact, std::uint64_t photon,
                         const TransportSettings& settings, PhotonOutcome* outcome = nullptr) {
    std::vector<Event> events;
    EventRecorder recorder(events);
    PhotonRandom random(9, photon);
    const PhotonOutcome result =
        tracePhoton(scene, {Point(impact, 0.0, -1.0), Direction(0, 0, 1)}, random, settings, &recorder);
    if (outcome) *outcome = result;
    return events;
}

std::size_t countOf(const std::vector<Event>& events, EventType type) {
    return static_cast<std::size_t>(
        std::count_if(events.begin(), events.end(), [&](const Event& e) { return e.type == type; }));
}

TEST(DropletDiffraction, OutlinesAreTheDiskAndTheProjectedEllipse) {
    const Sphere sphere(Point(1, 2, 3), 0.7);
    const auto disk = projectedOutline(sphere, Direction(1, 1, 0));
    ASSERT_TRUE(disk);
    EXPECT_DOUBLE_EQ(disk->a, 0.7);
    EXPECT_DOUBLE_EQ(disk->b, 0.7);
    EXPECT_NEAR(disk->e1.dot(Direction(1, 1, 0).vector()), 0.0, 1e-15);

    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 2).normalized()).toRotationMatrix();
    const Ellipsoid ellipsoid = Ellipsoid::fromSemiAxes(Point(0, 0, 0), Eigen::Vector3d(3.0, 2.0, 0.5), rotation);
    // Along a semi-axis: the other two.
    const auto front = projectedOutline(ellipsoid, Direction(rotation.col(2)));
    ASSERT_TRUE(front);
    EXPECT_NEAR(front->a, 3.0, 1e-12);
    EXPECT_NEAR(front->b, 2.0, 1e-12);
    EXPECT_NEAR(std::abs(front->e1.dot(rotation.col(0))), 1.0, 1e-12);
    // Any direction: the shadow's area is pi a b c sqrt(d.M d) (the ellipsoid x.M x <= 1 seen along d).
    for (const Direction& d : {Direction(1, 0.3, -2), Direction(0.2, 1, 0.1), Direction(-1, -1, 1)}) {
        const auto outline = projectedOutline(ellipsoid, d);
        ASSERT_TRUE(outline);
        const double area = std::numbers::pi * 3.0 * 2.0 * 0.5 * std::sqrt(d.dot(ellipsoid.matrix() * d.vector()));
        EXPECT_NEAR(std::numbers::pi * outline->a * outline->b, area, 1e-12 * area);
        EXPECT_NEAR(outline->e1.dot(d.vector()), 0.0, 1e-14);
        EXPECT_NEAR(outline->e1.dot(outline->e2), 0.0, 1e-14);
    }
    EXPECT_FALSE(projectedOutline(Box(Point(0, 0, 0), Point(1, 1, 1)), Direction(0, 0, 1)));
}

TEST(DropletDiffraction, ARayIsDiffractedExactlyWhenItPassesThroughTheRing) {
    const OpticalScene scene(waterDrop(), true);
    // Inside the outline: ray optics, never diffracted; in the ring a < b < sqrt(2) a: one diffraction and out;
    // beyond: untouched.
    for (double b : {0.0, 0.3, 0.99}) {
        const auto events = trace(scene, b * kRadius, 1, fraunhofer());
        EXPECT_EQ(countOf(events, EventType::Diffract), 0u) << b;
        EXPECT_GE(countOf(events, EventType::Refract) + countOf(events, EventType::Reflect), 1u) << b;
    }
    for (double b : {1.01, 1.2, 1.41}) {
        PhotonOutcome outcome;
        const auto events = trace(scene, b * kRadius, 2, fraunhofer(), &outcome);
        ASSERT_EQ(events.size(), 3u) << b;
        EXPECT_EQ(events[1].type, EventType::Diffract);
        EXPECT_EQ(events[1].shape, 0u);
        // At the middle of the chord through the halo: level with the droplet's centre.
        EXPECT_NEAR(events[1].position.z(), 0.0, 1e-12);
        EXPECT_EQ(outcome.fate, PhotonFate::Escaped);
        EXPECT_EQ(outcome.events.diffract, 1u);
        EXPECT_TRUE(outcome.metSurface) << "a diffracted photon is not unscattered";
    }
    for (double b : {1.42, 3.0}) {
        PhotonOutcome outcome;
        const auto events = trace(scene, b * kRadius, 3, fraunhofer(), &outcome);
        EXPECT_EQ(events.size(), 2u) << b;
        EXPECT_FALSE(outcome.metSurface);
    }
}

TEST(DropletDiffraction, ABeamLosesTwiceTheOutlineAndHalfOfThatIsDiffracted) {
    // A beam of radius 1.6 a, uniform: the outline takes 1/2.56 of it, the ring as much, 1 - 2/2.56 goes on.
    const OpticalScene scene(waterDrop(), true);
    constexpr int kPhotons = 20000;
    int diffracted = 0;
    int unscattered = 0;
    for (int i = 0; i < kPhotons; ++i) {
        PhotonRandom place(4, static_cast<std::uint64_t>(i));
        const double r = 1.6 * kRadius * std::sqrt(place.uniform());
        const double phi = 2.0 * std::numbers::pi * place.uniform();
        PhotonRandom random(5, static_cast<std::uint64_t>(i));
        const PhotonOutcome outcome = tracePhoton(
            scene, {Point(r * std::cos(phi), r * std::sin(phi), -1.0), Direction(0, 0, 1)}, random, fraunhofer());
        diffracted += outcome.events.diffract > 0;
        unscattered += !outcome.metSurface;
    }
    const double ring = 1.0 / 2.56;
    EXPECT_NEAR(diffracted / double(kPhotons), ring, monteCarloTolerance(ring, kPhotons));
    EXPECT_NEAR(unscattered / double(kPhotons), 1.0 - 2.0 * ring, monteCarloTolerance(1.0 - 2.0 * ring, kPhotons));
}

TEST(DropletDiffraction, DiffractedAnglesFollowTheAiryPatternOfTheDrop) {
    const OpticalScene scene(waterDrop(), true);
    std::vector<double> u;
    for (std::uint64_t i = 0; i < 20000; ++i) {
        const auto events = trace(scene, 1.2 * kRadius, i, fraunhofer());
        const Direction& out = events.back().direction;
        u.push_back(kSizeParameter * std::hypot(out.x(), out.y()));
    }
    std::sort(u.begin(), u.end());
    const double kept = airyEncircledEnergy(kSizeParameter);
    double worst = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const double model = airyEncircledEnergy(u[i]) / kept;
        worst = std::max(worst, std::abs(model - (static_cast<double>(i) + 0.5) / static_cast<double>(u.size())));
    }
    // Kolmogorov-Smirnov at 1 %: 1.63 / sqrt(n).
    EXPECT_LT(worst, 1.63 / std::sqrt(static_cast<double>(u.size())));
    // 83.8 % inside the first dark ring, theta = asin(3.832 / x) = 0.372 degrees.
    const auto inside = std::count_if(u.begin(), u.end(), [](double value) { return value < 3.8317; });
    EXPECT_NEAR(static_cast<double>(inside) / static_cast<double>(u.size()), 0.838, 0.01);
}

TEST(DropletDiffraction, TheStokesVectorPassesUnchanged) {
    const OpticalScene scene(waterDrop(), true);
    Polarisation light;
    light.stokes = StokesVector(1.0, 0.6, 0.0, 0.8);
    light.reference = Eigen::Vector3d::UnitX();
    std::vector<Event> events;
    EventRecorder recorder(events);
    PhotonRandom random(2, 0);
    tracePhoton(scene, {Point(1.3 * kRadius, 0.0, -1.0), Direction(0, 0, 1)}, random, fraunhofer(), &recorder, light);
    ASSERT_EQ(events.size(), 3u);
    ASSERT_TRUE(events[1].polarisation);
    EXPECT_EQ(events[1].polarisation->stokes, light.stokes);
    EXPECT_NEAR(events[1].polarisation->reference.dot(events[1].direction.vector()), 0.0, 1e-15);
    EXPECT_NEAR((events[1].polarisation->reference - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-2);
}

TEST(DropletDiffraction, WithoutItTheHaloesChangeNothing) {
    // The default model draws no extra random number: the same photons with and without haloes in the scene.
    const OpticalScene plain(waterDrop());
    const OpticalScene haloed(waterDrop(), true);
    for (double b : {0.2, 0.9, 1.2}) {
        for (std::uint64_t i = 0; i < 20; ++i) {
            PhotonOutcome first;
            PhotonOutcome second;
            trace(plain, b * kRadius, i, {}, &first);
            trace(haloed, b * kRadius, i, {}, &second);
            EXPECT_EQ(first.events, second.events);
            EXPECT_EQ(first.finalDirection.vector(), second.finalDirection.vector());
        }
    }
    EXPECT_THROW(trace(plain, 1.2 * kRadius, 0, fraunhofer()), std::logic_error);
}

TEST(DropletDiffraction, OfOverlappingHaloesTheNearestMiddleDiffracts) {
    // The pencil along z at x = y = 0 enters the halo of drop 0 (r = 1, 1.2 off the line) first, at z = 2.25, but the
    // middle of its chord through the halo of drop 1 (r = 0.2, 0.25 off the line) comes first: z = 2.6 against 3.
    const Scene two = sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                                    R"({"type": "sphere", "center": [1.2, 0, 3], "radius": 1, "medium": "water"},
                                       {"type": "sphere", "center": [-0.25, 0, 2.6], "radius": 0.2, "medium": "water"})",
                                    "");
    const OpticalScene scene(two, true);
    std::vector<Event> events;
    EventRecorder recorder(events);
    PhotonRandom random(1, 0);
    tracePhoton(scene, {Point(0, 0, -1), Direction(0, 0, 1)}, random, fraunhofer(), &recorder);
    ASSERT_GE(events.size(), 2u);
    EXPECT_EQ(events[1].type, EventType::Diffract);
    EXPECT_EQ(events[1].shape, 1u);
    EXPECT_NEAR(events[1].position.z(), 2.6, 1e-12);
}

TEST(DropletDiffraction, ADiffractedPhotonNeverMeetsItsDroplet) {
    // x = 2: the Airy pattern is wide, and from just outside the rim half of it points into the drop. Those turns
    // are drawn again: nothing but the diffraction happens.
    const Scene small = sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337})",
                                      R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.000169333,
                                          "medium": "water"})",
                                      "");
    const OpticalScene scene(small, true);
    for (std::uint64_t i = 0; i < 300; ++i) {
        PhotonOutcome outcome;
        const auto events = trace(scene, 1.01 * 0.000169333, i, fraunhofer(), &outcome);
        EXPECT_EQ(outcome.events.diffract, 1u) << i;
        EXPECT_EQ(outcome.events.refract + outcome.events.reflect, 0u) << i;
    }
}

TEST(DropletDiffraction, BoxesAreNotDiffracted) {
    const Scene box = sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5})",
                                    R"({"type": "box", "min": [-0.05, -0.05, -0.05], "max": [0.05, 0.05, 0.05],
                                        "medium": "glass"})",
                                    "");
    const OpticalScene scene(box, true);
    for (double b : {0.06, 0.07}) {
        PhotonOutcome outcome;
        trace(scene, b, 0, fraunhofer(), &outcome);
        EXPECT_EQ(outcome.events.diffract, 0u);
        EXPECT_FALSE(outcome.metSurface);
    }
}

}  // namespace
}  // namespace dropscope
