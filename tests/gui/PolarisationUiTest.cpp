// Polarisation in the app, driven through the panels as a user would: the "trace with" switch decides the
// model of the next trace (and live traces again), a linear source set in the Fire panel polarises the
// photons it emits, its reference stays perpendicular when the direction changes, a Stokes vector with
// |Q| > I is refused, undo brings the old state back, the paths can be coloured by DoLP, the event table
// shows each event's Stokes vector and the polarisation ellipse is drawn at the selected event.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "render/Layers.hpp"
#include "tally/AngularTally.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace dropscope::gui::testing {
namespace {

// A water sphere hit off its axis (sin of the first incidence 0.5), so the photons' polarisation varies.
constexpr const char* kOffAxisScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0.5, 0, -5], "direction": [0, 0, 1]}],
  "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
})";

// kAxisScene's ray linearly polarised at 30 degrees from x towards x cross z = -y.
constexpr const char* kLinearScene = R"({
  "dropscope": 1, "ambient": "air",
  "media": {"air": {"n": 1}, "water": {"n": 1.3337}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "ray", "origin": [0, 0, -5], "direction": [0, 0, 1],
               "polarisation": {"linear_deg": 30, "reference": [1, 0, 0]}}],
  "view": {"eye": [6, 3, -4], "target": [0, 0, 0]}
})";

// Stokes vectors computed twice in double precision (the engine, the closed form here).
constexpr double kStokesRounding = 1e-12;
// The event table shows 4 decimals (DoLP 3).
constexpr double kTableDigits = 5e-4;
// Line vertices are floats relative to the anchor, here the sphere's centre, a few units away.
constexpr double kFloatRounding = 1e-5;

bool anyEventPolarised(const TraceResult& result) {
    for (const PhotonPath& path : result.paths) {
        for (const Event& event : path.events) {
            if (event.polarisation) return true;
        }
    }
    return false;
}

std::vector<render::Colour> coloursOf(const render::LineBatch& lines, std::size_t count) {
    std::vector<render::Colour> colours;
    for (std::size_t v = 0; v < count && v < lines.vertices().size(); ++v)
        colours.push_back(lines.vertices()[v].colour);
    return colours;
}

Point worldOf(const render::LineVertex& vertex, const render::Anchor& anchor) {
    return anchor.origin + Point(vertex.position[0], vertex.position[1], vertex.position[2]);
}

TEST(PolarisationUi, TheSwitchDecidesTheModelOfTheNextTraceAndLiveTracesAgain) {
    AppHarness harness(kLinearScene);
    ASSERT_EQ(harness.state().traces.fire.polarisation, PolarisationModel::Stokes) << "the default";
    fire(harness);
    EXPECT_TRUE(shownTrace(harness).tallies.get<AngularTally>().stokes());
    EXPECT_TRUE(anyEventPolarised(shownTrace(harness)));
    harness.press('R');
    ASSERT_TRUE(harness.state().traces.rayTree);
    const auto& emitted = harness.state().traces.rayTree->nodes.front().event.polarisation;
    ASSERT_TRUE(emitted) << "the ray tree carries the source's polarisation";
    EXPECT_NEAR((emitted->stokes - StokesVector(1.0, 0.5, std::sqrt(0.75), 0.0)).norm(), 0.0, kStokesRounding);

    // "none" in the Fire panel: live traces the photons and the ray tree again, without polarisation.
    const std::uint64_t shown = harness.state().traces.shownId;
    ASSERT_TRUE(harness.choose("trace with", "none (unpolarised Fresnel)"));
    EXPECT_EQ(harness.state().traces.fire.polarisation, PolarisationModel::None);
    ASSERT_TRUE(harness.waitForNewTrace(shown));
    ASSERT_EQ(harness.state().traces.fired.polarisation, PolarisationModel::None);
    EXPECT_FALSE(shownTrace(harness).tallies.get<AngularTally>().stokes()) << "no Stokes columns";
    EXPECT_FALSE(anyEventPolarised(shownTrace(harness)));
    for (const RayTreeNode& node : harness.state().traces.rayTree->nodes) EXPECT_FALSE(node.event.polarisation);

    // Without live, the next trace fired uses the switch too.
    harness.state().traces.fire.live = false;
    ASSERT_TRUE(harness.choose("trace with", "Stokes vectors"));
    harness.frames(2);
    EXPECT_EQ(harness.state().traces.fired.polarisation, PolarisationModel::None) << "not traced again";
    fire(harness);
    EXPECT_TRUE(shownTrace(harness).tallies.get<AngularTally>().stokes());
}

TEST(PolarisationUi, ALinearSourceSetInTheFirePanelPolarisesItsPhotonsAndUndoRestoresIt) {
    AppHarness harness(kAxisScene);
    ASSERT_TRUE(harness.choose("polarisation", "linear"));
    EXPECT_EQ(firstSource(harness).polarisation.kind, PolarisationKind::Linear);
    EXPECT_EQ(firstSource(harness).polarisation.reference, Eigen::Vector3d::UnitX()) << "a reference was set";
    EXPECT_NE(harness.state().ui.status.text().find("reference"), std::string::npos)
        << harness.state().ui.status.text();
    harness.frame();
    ASSERT_TRUE(harness.typeInto("angle (deg)", "30"));
    EXPECT_FALSE(harness.state().ui.status.error()) << harness.state().ui.status.text();
    EXPECT_EQ(firstSource(harness).polarisation.linearDeg, 30.0);

    fire(harness);
    ASSERT_FALSE(shownTrace(harness).paths.empty());
    for (const PhotonPath& path : shownTrace(harness).paths) {
        const Event& emission = path.events.front();
        ASSERT_TRUE(emission.polarisation);
        // Linear at A = 30 degrees from the reference: Q = cos 2A, U = sin 2A.
        EXPECT_EQ(emission.polarisation->reference, Eigen::Vector3d::UnitX());
        const double twice = 2.0 * 30.0 * std::numbers::pi / 180.0;
        EXPECT_NEAR((emission.polarisation->stokes - StokesVector(1.0, std::cos(twice), std::sin(twice), 0.0)).norm(),
                    0.0, kStokesRounding);
    }

    // Typing "30" was one undo step, choosing "linear" another.
    harness.press('Z', true);
    EXPECT_EQ(firstSource(harness).polarisation.kind, PolarisationKind::Linear);
    EXPECT_EQ(firstSource(harness).polarisation.linearDeg, 0.0);
    harness.press('Z', true);
    EXPECT_EQ(firstSource(harness).polarisation, SourcePolarisation{});
    harness.press('Y', true);
    harness.press('Y', true);
    EXPECT_EQ(firstSource(harness).polarisation.linearDeg, 30.0);
}

TEST(PolarisationUi, ChangingTheDirectionKeepsTheReferencePerpendicular) {
    AppHarness harness(kAxisScene);
    ASSERT_TRUE(harness.choose("polarisation", "linear"));
    ASSERT_EQ(firstSource(harness).polarisation.reference, Eigen::Vector3d::UnitX());
    harness.frame();
    ASSERT_TRUE(harness.typeInto("direction (A)", "1"));  // (0, 0, 1) becomes (1, 0, 1)
    const Source& source = firstSource(harness);
    EXPECT_NEAR((source.direction.vector() - Eigen::Vector3d(1, 0, 1).normalized()).norm(), 0.0, kStokesRounding);
    EXPECT_NEAR(source.polarisation.reference.dot(source.direction.vector()), 0.0, kStokesRounding);
    EXPECT_NEAR((source.polarisation.reference - Eigen::Vector3d(1, 0, -1).normalized()).norm(), 0.0, kStokesRounding);
    EXPECT_FALSE(harness.state().ui.status.error()) << harness.state().ui.status.text();
    EXPECT_NE(harness.state().ui.status.text().find("projected"), std::string::npos)
        << harness.state().ui.status.text();
}

TEST(PolarisationUi, AStokesVectorWithQAboveIIsRefusedAndNothingChanges) {
    AppHarness harness(kAxisScene);
    ASSERT_TRUE(harness.choose("polarisation", "linear"));
    harness.frame();
    ASSERT_TRUE(harness.choose("polarisation", "Stokes vector"));
    ASSERT_EQ(firstSource(harness).polarisation.kind, PolarisationKind::Stokes);
    EXPECT_EQ(firstSource(harness).polarisation.stokes, StokesVector(1.0, 1.0, 0.0, 0.0)) << "the linear state";
    const std::uint64_t revision = harness.state().scene.document().revision();
    harness.frame();
    ASSERT_TRUE(harness.typeInto("I Q U V", "0.5"));  // I = 0.5 < Q = 1
    EXPECT_TRUE(harness.state().ui.status.error());
    EXPECT_NE(harness.state().ui.status.text().find("must not exceed I^2"), std::string::npos)
        << harness.state().ui.status.text();
    EXPECT_EQ(harness.state().scene.document().revision(), revision);
    EXPECT_EQ(firstSource(harness).polarisation.stokes, StokesVector(1.0, 1.0, 0.0, 0.0));
}

TEST(PolarisationUi, ColouringByDolpChangesThePathColours) {
    AppHarness harness(kOffAxisScene);
    fire(harness);
    const std::vector<PhotonPath>& paths = shownTrace(harness).paths;
    const render::Anchor anchor{};  // the sphere's centre, the origin
    // The colours of the segments outside the sphere, then of its chords (kept apart: render/Chords.hpp).
    const auto coloured = [&](render::PathColouring colouring) {
        render::LineBatch lines(anchor);
        render::LineBatch chords(anchor);
        const render::ChordSplit split{harness.state().scene.document().octree(), chords};
        render::addPhotonPaths(lines, paths, 1.0, colouring, &split);
        return std::pair{coloursOf(lines, lines.vertices().size()), coloursOf(chords, chords.vertices().size())};
    };
    const auto drawn = [&](std::size_t lineVertices) {
        const render::SceneLayers& layers = harness.app().viewport().layers();
        return std::pair{coloursOf(layers.lines, lineVertices),
                         coloursOf(layers.chords, layers.chords.vertices().size())};
    };
    const auto byWeight = coloured(render::PathColouring::Weight);
    const auto byDolp = coloured(render::PathColouring::Dolp);
    ASSERT_NE(byWeight, byDolp);
    ASSERT_FALSE(byWeight.second.empty());
    // Nothing else is drawn before the paths: no event is selected and there is no ray tree.
    EXPECT_EQ(drawn(byWeight.first.size()), byWeight);

    ASSERT_TRUE(harness.choose("colour", "DoLP"));
    EXPECT_EQ(harness.state().view.layers.pathColouring, render::PathColouring::Dolp);
    EXPECT_EQ(drawn(byDolp.first.size()), byDolp);
}

TEST(PolarisationUi, TheEventTableShowsEachEventsStokesVector) {
    AppHarness harness(kOffAxisScene);
    fire(harness);
    harness.press(kKeyRight);  // photon 0, its emission
    harness.press(kKeyRight);  // its first refraction
    ASSERT_EQ(harness.state().traces.selectedEvent, 1);
    const auto& events = shownTrace(harness).paths.front().events;
    for (std::size_t k = 0; k < 3; ++k) {
        ASSERT_TRUE(events[k].polarisation);
        const StokesVector& stokes = events[k].polarisation->stokes;
        const std::string row = "event " + std::to_string(k) + " ";
        for (const auto& [column, value] :
             {std::pair{"I", stokes[0]}, std::pair{"Q", stokes[1]}, std::pair{"U", stokes[2]},
              std::pair{"V", stokes[3]}, std::pair{"DoLP", degreeOfLinearPolarisation(stokes)}}) {
            const auto cell = harness.item(row + column);
            ASSERT_TRUE(cell);
            EXPECT_NEAR(std::stod(cell->text), value, kTableDigits * std::max(1.0, std::abs(value)))
                << row << column << ": " << cell->text;
        }
    }
    // The first refraction, at 30 degrees, leaves the light polarised 0.5 %: too little to draw.
    ASSERT_LT(degreeOfPolarisation(events[1].polarisation->stokes), render::kUnpolarisedDegree);
    ASSERT_TRUE(harness.item("event polarisation"));
    EXPECT_EQ(harness.item("event polarisation")->text.rfind("unpolarised", 0), 0u);

    // Traced without polarisation: "-" in every Stokes cell.
    harness.state().traces.fire.polarisation = PolarisationModel::None;
    fire(harness);
    ASSERT_EQ(harness.state().traces.selectedEvent, 1);
    harness.frame();
    for (const char* column : {"I", "Q", "U", "V", "DoLP"}) {
        const auto cell = harness.item(std::string("event 1 ") + column);
        ASSERT_TRUE(cell);
        EXPECT_EQ(cell->text, "-");
    }
    EXPECT_EQ(harness.item("event polarisation")->text.rfind("no polarisation", 0), 0u);
}

TEST(PolarisationUi, TheEllipseIsDrawnAtTheSelectedEventAcrossItsDirection) {
    AppHarness harness(kLinearScene);
    fire(harness);
    harness.press(kKeyRight);  // photon 0, its emission at (0, 0, -5) along z
    const render::LineBatch& lines = harness.app().viewport().layers().lines;
    const Event& emission = shownTrace(harness).paths.front().events.front();
    ASSERT_EQ(emission.position, Point(0.0, 0.0, -5.0));
    const double size = render::kEllipseSize * harness.app().viewport().sceneBounds().diagonal().norm();
    // Linear at 30 degrees from x towards x cross z = -y: a segment along (cos 30, -sin 30, 0), drawn first,
    // then the line along the direction.
    const Eigen::Vector3d axis(std::cos(std::numbers::pi / 6), -std::sin(std::numbers::pi / 6), 0.0);
    const render::Anchor anchor{harness.app().viewport().sceneBounds().center()};
    std::size_t ellipse = 0;
    while (ellipse < lines.vertices().size() && lines.vertices()[ellipse].colour == render::kEllipseColour) ++ellipse;
    ASSERT_GT(ellipse, 2u);
    for (std::size_t v = 0; v + 2 < ellipse; ++v) {
        const Eigen::Vector3d offset = worldOf(lines.vertices()[v], anchor) - emission.position;
        EXPECT_NEAR(offset.z(), 0.0, kFloatRounding) << "in the plane across the direction";
        EXPECT_NEAR((offset - offset.dot(axis) * axis).norm(), 0.0, kFloatRounding) << "along the field";
        EXPECT_LE(offset.norm(), size + kFloatRounding);
    }
    EXPECT_NEAR((worldOf(lines.vertices()[ellipse - 1], anchor) - (emission.position + size * Point::UnitZ())).norm(),
                0.0, kFloatRounding);

    // The next event, the refraction into the sphere head on at (0, 0, -1): the ellipse moves there.
    harness.press(kKeyRight);
    const Point next = shownTrace(harness).paths.front().events[1].position;
    ASSERT_NEAR(next.z(), -1.0, 1e-9);
    EXPECT_NEAR((worldOf(lines.vertices().front(), anchor) - next).norm(), size, kFloatRounding);
}

}  // namespace
}  // namespace dropscope::gui::testing
