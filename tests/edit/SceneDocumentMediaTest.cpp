// SceneDocument media, ambient and source edits: validated, absorption computed as the loader does,
// undoable.
#include "edit/SceneDocument.hpp"
#include "edit/SceneDocumentTestSupport.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace dropscope {
namespace {

using namespace test;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

TEST(SceneDocument, MediaEditsValidateComputeAbsorptionAndUndo) {
    SceneDocument document(smallScene());
    const MediumId ink = document.addMedium({"ink", 1.34, {}, 0.5, 0.0});
    EXPECT_EQ(ink, 3u);
    EXPECT_EQ(document.media()[ink].absorptionPerUnit, 0.5);
    EXPECT_EQ(document.undoLabel(), "add medium \"ink\"");
    document.setMedium(1, {"water", 1.33, 2e-9, {}, 0.0});
    // kappa to absorption exactly as the loader does it.
    const Scene loaded = parseScene(R"({"dropscope": 1, "media": {"water": {"n": 1.33, "kappa": 2e-9}}})", "w.json");
    EXPECT_EQ(document.media()[1].absorptionPerUnit, loaded.media[0].absorptionPerUnit);
    EXPECT_GT(document.media()[1].absorptionPerUnit, 0.0);

    const Snapshot before(document);
    EXPECT_EQ(refusalOf([&] { document.addMedium({"", 1.0, {}, {}, 0.0}); }), "a medium name must not be empty");
    EXPECT_EQ(refusalOf([&] {
                  document.addMedium({"glass", 1.0, {}, {}, 0.0});
              }),
              "medium name \"glass\" is already used");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", 0.0, {}, {}, 0.0}); }), "n must be finite and > 0");
    EXPECT_EQ(refusalOf([&] { document.setMedium(1, {"water", kNan, {}, {}, 0.0}); }), "n must be finite and > 0");
    EXPECT_EQ(refusalOf([&] {
                  document.setMedium(1, {"water", 1.3, 1e-9, 0.1, 0.0});
              }),
              "give either kappa or sigma, not both");
    EXPECT_EQ(refusalOf([&] {
                  document.setMedium(1, {"water", 1.3, -1e-9, {}, 0.0});
              }),
              "kappa must be finite and >= 0");
    EXPECT_EQ(refusalOf([&] {
                  document.setMedium(1, {"water", 1.3, {}, -1.0, 0.0});
              }),
              "sigma must be finite and >= 0");
    EXPECT_EQ(refusalOf([&] {
                  document.setMedium(1, {"air", 1.3, {}, {}, 0.0});
              }),
              "medium name \"air\" is already used");
    EXPECT_EQ(refusalOf([&] { document.setMedium(9, {"x", 1.3, {}, {}, 0.0}); }), "medium 9 is not defined (4 media)");
    EXPECT_EQ(refusalOf([&] { document.setAmbient(9); }), "medium 9 is not defined (4 media)");
    EXPECT_EQ(Snapshot(document), before);

    document.setAmbient(ink);
    EXPECT_EQ(document.ambient(), ink);
    document.undo();
    EXPECT_EQ(document.ambient(), 0u);
    document.undo();
    EXPECT_EQ(document.media()[1].n, 1.333);
    EXPECT_EQ(document.media()[1].kappa, 1e-9);
    document.undo();
    EXPECT_EQ(document.media().size(), 3u);
}

TEST(SceneDocument, SourceEditsValidateAndUndo) {
    SceneDocument document(smallScene());
    Source beam;
    beam.type = SourceType::Beam;
    beam.origin = Point(0, 0, -20);
    beam.direction = Direction(0, 0, 1);
    beam.radius = 2.0;
    document.setSources({beam});
    EXPECT_EQ(document.sources().size(), 1u);
    EXPECT_EQ(document.sources()[0].type, SourceType::Beam);
    Source bad = beam;
    bad.radius = 0.0;
    EXPECT_EQ(refusalOf([&] { document.setSources({beam, bad}); }), "source 1: beam radius must be finite and > 0");
    bad = beam;
    bad.direction = Direction(0, 0, 0);
    EXPECT_EQ(refusalOf([&] { document.setSources({bad}); }), "source 0: direction must be a finite, non-zero vector");
    document.undo();
    EXPECT_EQ(document.sources()[0].type, SourceType::Ray);
}

}  // namespace
}  // namespace dropscope
