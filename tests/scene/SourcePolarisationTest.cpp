// The "polarisation" of beam and ray sources (docs/scene-format.md, "Sources"): the three forms, what they
// mean, and every error at its JSON path.
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"
#include "scene/SceneWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace dropscope {
namespace {

using test::sceneErrorOf;

std::string sceneWithSource(const std::string& source) { return R"({"dropscope": 1, "sources": [)" + source + "]}"; }

std::string beamWith(const std::string& polarisation) {
    return sceneWithSource(R"({"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 2], "radius": 1,
                               "polarisation": )" +
                           polarisation + "}");
}

SourcePolarisation readPolarisation(const std::string& polarisation) {
    return parseScene(beamWith(polarisation), "scene.json").sources.at(0).polarisation;
}

TEST(SourcePolarisation, IsUnpolarisedUnlessGiven) {
    const Scene scene = parseScene(sceneWithSource(R"({"type": "ray", "origin": [0, 0, 0], "direction": [1, 0, 0]},
                           {"type": "point", "origin": [0, 0, 0], "polarisation": "unpolarised"})"),
                                   "scene.json");
    for (const Source& source : scene.sources) {
        EXPECT_EQ(source.polarisation.kind, PolarisationKind::Unpolarised);
        EXPECT_EQ(source.polarisation.unitStokes(), StokesVector(1, 0, 0, 0));
    }
    EXPECT_EQ(readPolarisation(R"("unpolarised")").kind, PolarisationKind::Unpolarised);
}

TEST(SourcePolarisation, LinearLightAtAnAngleFromTheReference) {
    const SourcePolarisation linear = readPolarisation(R"({"linear_deg": 30, "reference": [0, 2, 0]})");
    EXPECT_EQ(linear.kind, PolarisationKind::Linear);
    EXPECT_EQ(linear.linearDeg, 30.0);
    EXPECT_EQ(linear.reference, Eigen::Vector3d(0, 2, 0));  // as given; emission normalises it
    const StokesVector unit = linear.unitStokes();
    EXPECT_NEAR(unit[1], 0.5, 1e-15);                   // cos 60 degrees
    EXPECT_NEAR(unit[2], std::sqrt(3.0) / 2.0, 1e-15);  // sin 60 degrees
    EXPECT_EQ(unit[3], 0.0);
}

TEST(SourcePolarisation, StokesVectorsAreScaledToUnitPower) {
    const SourcePolarisation stokes = readPolarisation(R"({"stokes": [2, 0, 0, -2], "reference": [1, 0, 0]})");
    EXPECT_EQ(stokes.kind, PolarisationKind::Stokes);
    EXPECT_EQ(stokes.stokes, StokesVector(2, 0, 0, -2));
    EXPECT_EQ(stokes.unitStokes(), StokesVector(1, 0, 0, -1));
    // Fully polarised in decimals: 0.36 + 0.64 rounds above 1, within the documented slack.
    const SourcePolarisation decimal = readPolarisation(R"({"stokes": [1, 0.6, 0.8, 0], "reference": [1, 0, 0]})");
    EXPECT_LE(decimal.unitStokes().tail<3>().norm(), 1.0);
}

TEST(SourcePolarisation, TheTolerancesAreWhereTheyAreDocumented) {
    // A reference 1e-7 of a radian off perpendicular (written with seven digits) passes; 2e-6 is refused.
    EXPECT_NO_THROW(readPolarisation(R"({"linear_deg": 0, "reference": [1, 0, 1e-7]})"));
    EXPECT_NE(sceneErrorOf(beamWith(R"({"linear_deg": 0, "reference": [1, 0, 2e-6]})")), "no error");
    // A degree of polarisation of 1 + 1e-13 is within the slack of 1e-12 on its square; 1 + 1e-11 is not.
    EXPECT_NO_THROW(readPolarisation(R"({"stokes": [1, 1.0000000000001, 0, 0], "reference": [1, 0, 0]})"));
    EXPECT_NE(sceneErrorOf(beamWith(R"({"stokes": [1, 1.00000000001, 0, 0], "reference": [1, 0, 0]})")), "no error");
}

TEST(SourcePolarisation, HugeAndTinyNumbersAreJudgedByTheirRatios) {
    // Squares of 1e200 overflow and of 1e-200 underflow: neither may let a bad state through or refuse a good one.
    EXPECT_NO_THROW(readPolarisation(R"({"linear_deg": 0, "reference": [1e200, 0, 0]})"));
    EXPECT_NO_THROW(readPolarisation(R"({"linear_deg": 0, "reference": [1e-200, 0, 0]})"));
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 0, "reference": [1e200, 0, 1e200]})")),
              "scene.json: sources[0].polarisation.reference: must be perpendicular to the direction (their cosine "
              "is 0.707)");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 0, "reference": [1e-200, 0, 1e-200]})")),
              "scene.json: sources[0].polarisation.reference: must be perpendicular to the direction (their cosine "
              "is 0.707)");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"stokes": [1e200, 1e201, 0, 0], "reference": [1, 0, 0]})")),
              "scene.json: sources[0].polarisation.stokes: Q^2 + U^2 + V^2 must not exceed I^2 (the degree of "
              "polarisation is 10)");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"stokes": [1e-200, 1e-199, 0, 0], "reference": [1, 0, 0]})")),
              "scene.json: sources[0].polarisation.stokes: Q^2 + U^2 + V^2 must not exceed I^2 (the degree of "
              "polarisation is 10)");
    const SourcePolarisation tiny = readPolarisation(R"({"stokes": [1e-200, 0, 1e-200, 0], "reference": [1, 0, 0]})");
    EXPECT_EQ(tiny.unitStokes(), StokesVector(1, 0, 1, 0));
}

TEST(SourcePolarisation, EveryErrorNamesItsPath) {
    const std::string at = "scene.json: sources[0].polarisation";
    EXPECT_EQ(sceneErrorOf(beamWith(R"("unpolarized")")),
              at + R"(: unknown polarisation "unpolarized" (known: "unpolarised", {"linear_deg": A, "reference": )"
                   R"([x, y, z]} or {"stokes": [I, Q, U, V], "reference": [x, y, z]}))");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"reference": [1, 0, 0]})")),
              at + R"(: expected one of "unpolarised", {"linear_deg": A, "reference": [x, y, z]} or )"
                   R"({"stokes": [I, Q, U, V], "reference": [x, y, z]})");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 10})")), at + R"(: missing required key "reference")");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 10, "stokes": [1, 0, 0, 0], "reference": [1, 0, 0]})")),
              at + R"(: unknown key "stokes" (valid keys: linear_deg, reference))");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": "ten", "reference": [1, 0, 0]})")),
              at + ".linear_deg: expected a number, got string");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 10, "reference": [1, 0, 1]})")),
              at + ".reference: must be perpendicular to the direction (their cosine is 0.707)");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"linear_deg": 10, "reference": [0, 0, 0]})")),
              at + ".reference: must be a finite, non-zero vector");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"stokes": [0, 0, 0, 0], "reference": [1, 0, 0]})")),
              at + ".stokes: I must be > 0");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"stokes": [1, 0.8, 0.8, 0], "reference": [1, 0, 0]})")),
              at + ".stokes: Q^2 + U^2 + V^2 must not exceed I^2 (the degree of polarisation is 1.13)");
    EXPECT_EQ(sceneErrorOf(beamWith(R"({"stokes": [1, 0, 0], "reference": [1, 0, 0]})")),
              at + ".stokes: must be [I, Q, U, V], four numbers");
    EXPECT_EQ(
        sceneErrorOf(sceneWithSource(
            R"({"type": "point", "origin": [0, 0, 0], "polarisation": {"linear_deg": 0, "reference": [1, 0, 0]}})")),
        at + ": a point source is unpolarised only");
}

TEST(SourcePolarisation, CheckPolarisationRefusesWhatTheReaderRefuses) {
    Source source;
    source.type = SourceType::Beam;
    source.radius = 1.0;
    source.direction = Direction(0, 0, 1);
    source.polarisation = {PolarisationKind::Linear, 20.0, unpolarisedStokes(), Eigen::Vector3d(0, 1, 0)};
    EXPECT_NO_THROW(checkPolarisation(source));
    source.direction = Direction(0, 1, 1);  // the reference is no longer across the beam
    EXPECT_THROW(checkPolarisation(source), std::invalid_argument);
    source.direction = Direction(1, 0, 0);
    source.polarisation.linearDeg = std::nan("");
    EXPECT_THROW(checkPolarisation(source), std::invalid_argument);
    source.polarisation = {PolarisationKind::Stokes, 0.0, StokesVector(1, 0, 0, 1.5), Eigen::Vector3d(0, 1, 0)};
    EXPECT_THROW(checkPolarisation(source), std::invalid_argument);
    source.type = SourceType::PointSource;
    source.polarisation.stokes = StokesVector(1, 0, 0, 1);
    EXPECT_THROW(checkPolarisation(source), std::invalid_argument);
}

TEST(SourcePolarisation, IsWrittenAsGiven) {
    const Scene scene = parseScene(sceneWithSource(R"({"type": "ray", "origin": [0, 0, 0], "direction": [0, 0, 1],
                            "polarisation": {"linear_deg": 12.5, "reference": [0, 3, 0]}},
                           {"type": "ray", "origin": [0, 0, 0], "direction": [0, 0, 1],
                            "polarisation": {"stokes": [1, 0.1, -0.2, 0.3], "reference": [1, 1, 0]}},
                           {"type": "ray", "origin": [0, 0, 0], "direction": [0, 0, 1]})"),
                                   "scene.json");
    const Scene reread = parseScene(sceneToJson(scene), "written.json");
    ASSERT_EQ(reread.sources.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(reread.sources[i].polarisation, scene.sources[i].polarisation) << i;
    EXPECT_EQ(sceneToJson(scene).find("unpolarised"), std::string::npos);  // the default is not written
}

}  // namespace
}  // namespace dropscope
