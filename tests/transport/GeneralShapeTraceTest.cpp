// Photons through parametric and implicit shapes: the same droplet written as a Sphere, a parametric
// sphere, a scaled parametric sphere and an implicit superellipsoid with exponents 1 gives the same
// tally, photon for photon (the Stokes sums to rounding); every preset of the gallery scene loses no photon to
// geometry.
#include "TallyExpectations.hpp"
#include "TransportFixtures.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

using testing::sceneFromJson;

TraceSettings settingsFor(std::uint64_t photons) {
    TraceSettings settings;
    settings.photons = photons;
    settings.threads = 2;
    settings.paths = 0;
    settings.seed = 77;
    return settings;
}

// Normals agree with the sphere's to ~1e-12, and so do the Stokes vectors turned into their planes of
// incidence: 1e-9 of the photons' power leaves a wide margin.
constexpr double kStokesTolerance = 1e-9;

void expectSameTally(const TraceResult& a, const TraceResult& b) {
    test::expectSameTallyToRounding(a, b, kStokesTolerance);
}

TraceResult traceDroplet(const std::string& droplet) {
    const Scene scene =
        sceneFromJson(R"("air": {"n": 1.0}, "water": {"n": 1.3337, "kappa": 2e-4})", droplet,
                      R"({"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 0.9})");
    return test::traceStandard(OpticalScene(scene), scene.sources, settingsFor(4000));
}

TEST(GeneralShapeTrace, EveryFormOfTheSameDropletTracesTheSame) {
    // Hit points agree with the sphere's to ~1e-12, far below anything that could turn a photon's
    // random choice (Fresnel draw, absorption) or its escape bin.
    const TraceResult sphere =
        traceDroplet(R"({"type": "sphere", "center": [0.1, 0, 0], "radius": 0.8, "medium": "water"})");
    EXPECT_GT(test::fates(sphere).events().refract, 2500u);  // most photons cross the droplet
    expectSameTally(traceDroplet(R"({"type": "parametric", "preset": "sphere", "radius": 0.8,
        "transform": {"translation": [0.1, 0, 0]}, "medium": "water"})"),
                    sphere);
    expectSameTally(traceDroplet(R"({"type": "parametric", "preset": "sphere", "radius": 2,
        "transform": {"scale": 0.4, "rotation": {"axis": [1, 2, 3], "angle_deg": 70}, "translation": [0.1, 0, 0]},
        "medium": "water"})"),
                    sphere);
    expectSameTally(traceDroplet(R"({"type": "implicit", "preset": "superellipsoid", "semi_axes": [0.8, 0.8, 0.8],
        "exponents": [1, 1], "transform": {"translation": [0.1, 0, 0]}, "medium": "water"})"),
                    sphere);
}

TEST(GeneralShapeTrace, AStretchedParametricSphereTracesAsTheEllipsoid) {
    const TraceResult ellipsoid =
        traceDroplet(R"({"type": "ellipsoid", "center": [0, 0.1, 0], "semi_axes": [1.2, 0.8, 0.5],
        "rotation": {"axis": [0, 1, 1], "angle_deg": 35}, "medium": "water"})");
    expectSameTally(traceDroplet(R"({"type": "parametric", "preset": "ellipsoid", "semi_axes": [1.2, 0.8, 0.5],
        "transform": {"rotation": {"axis": [0, 1, 1], "angle_deg": 35}, "translation": [0, 0.1, 0]}, "medium": "water"})"),
                    ellipsoid);
}

TEST(GeneralShapeTrace, TheGalleryLosesNoPhotonToGeometry) {
    const Scene scene = loadScene(DROPSCOPE_SOURCE_DIR "/assets/scenes/shapes_gallery.json");
    TraceSettings settings = settingsFor(3000);
    const TraceResult result = test::traceStandard(OpticalScene(scene), scene.sources, settings);
    const FateTally& tally = test::fates(result);
    EXPECT_EQ(tally.photons(), 3000u);
    EXPECT_EQ(tally.lost(LostReason::NoExit), 0u);
    EXPECT_EQ(tally.lost(LostReason::MediumMismatch), 0u);
    EXPECT_EQ(tally.lost(LostReason::UndefinedNormal), 0u);
    EXPECT_GT(tally.events().refract, 1500u);  // the shapes are met, not missed
}

}  // namespace
}  // namespace dropscope
