// Scene key "detectors": plane, far_field and shape_absorption detectors, their defaults, their errors at the
// JSON path of the bad value, and the writer's round trip (docs/scene-format.md, "Detectors").
#include "scene/SceneLoader.hpp"
#include "scene/SceneTestSupport.hpp"
#include "scene/SceneWriter.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dropscope {
namespace {

using test::sceneErrorOf;

std::string withDetectors(const std::string& detectors) {
    return R"({"dropscope": 1, "detectors": [)" + detectors + "]}";
}

constexpr const char* kPlane =
    R"({"type": "plane", "name": "screen", "center": [0, 0, 5], "normal": [0, 0, -2], "up": [0, 1, 0],)"
    R"( "size": [4, 2], "pixels": [8, 4]})";
constexpr const char* kSky = R"({"type": "far_field", "name": "sky", "look": [0, 0, 1], "up": [0, 1, 0],)"
                             R"( "fov_deg": 110, "pixels": [20, 10]})";

TEST(DetectorReader, ReadsEachTypeWithDefaults) {
    const Scene scene = parseScene(withDetectors(std::string(kPlane) + ", " + kSky +
                                                 R"(, {"type": "shape_absorption", "name": "a_1", "record": 7})"),
                                   "scene.json");
    ASSERT_EQ(scene.detectors.size(), 3u);
    const Detector& plane = scene.detectors[0];
    EXPECT_EQ(plane.type, DetectorType::Plane);
    EXPECT_EQ(plane.name, "screen");
    EXPECT_EQ(plane.normal.vector(), Eigen::Vector3d(0, 0, -1));
    EXPECT_EQ(plane.size[0], 4.0);
    EXPECT_EQ(plane.size[1], 2.0);
    EXPECT_EQ(plane.pixels.nx, 8);
    EXPECT_EQ(plane.pixels.ny, 4);
    EXPECT_EQ(plane.side, DetectorSide::Both);
    EXPECT_FALSE(plane.absorbing);
    EXPECT_EQ(plane.record, 0u);
    const Detector& sky = scene.detectors[1];
    EXPECT_EQ(sky.type, DetectorType::FarField);
    EXPECT_EQ(sky.projection, FarFieldProjection::Equidistant);
    EXPECT_EQ(sky.fovDeg, 110.0);
    EXPECT_EQ(scene.detectors[2].type, DetectorType::ShapeAbsorption);
    EXPECT_EQ(scene.detectors[2].record, 7u);
}

TEST(DetectorReader, PlaneFrameIsVUpAndUVCrossNormal) {
    const Scene scene = parseScene(withDetectors(kPlane), "scene.json");
    const PlaneFrame frame = planeFrame(scene.detectors[0]);
    // normal -z, up +y: u = y x (-z) = -x. Seen from the front (from -z looking towards +z), -x is to the right.
    EXPECT_EQ(frame.v, Eigen::Vector3d(0, 1, 0));
    EXPECT_EQ(frame.u, Eigen::Vector3d(-1, 0, 0));
}

TEST(DetectorReader, ErrorsNameTheJsonPath) {
    EXPECT_EQ(sceneErrorOf(withDetectors(std::string(kSky) + ", " + kSky)),
              "scene.json: detectors[1].name: another detector is already named \"sky\"");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "camera", "name": "x"})")),
              "scene.json: detectors[0].type: unknown detector type \"camera\" (known: plane, far_field, "
              "shape_absorption)");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "shape_absorption", "name": "my screen"})")),
              "scene.json: detectors[0].name: a detector name is 1 to 64 letters, digits, '_' or '-', got \"my "
              "screen\"");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "shape_absorption", "name": ""})")),
              "scene.json: detectors[0].name: a detector name is 1 to 64 letters, digits, '_' or '-', got \"\"");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [0, 2, 0], "size": [1, 1], "pixels": [2, 2]})")),
              "scene.json: detectors[0].up: up must not be along the normal");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "far_field", "name": "p", "look": [0, 0, 1], "up": [0, 1, 0],)"
                                         R"( "projection": "perspective", "fov_deg": 180, "pixels": [2, 2]})")),
              "scene.json: detectors[0].fov_deg: fov_deg must be > 0 and < 180 for the perspective projection");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "far_field", "name": "p", "look": [0, 0, 1], "up": [0, 1, 0],)"
                                         R"( "fov_deg": 361, "pixels": [2, 2]})")),
              "scene.json: detectors[0].fov_deg: fov_deg must be > 0 and <= 360 for the equidistant projection");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [1, 0, 0], "size": [1, 1], "pixels": [0, 2]})")),
              "scene.json: detectors[0].pixels[0]: must be from 1 to 1048576");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [1, 0, 0], "size": [1, 1], "pixels": [1024, 1025]})")),
              "scene.json: detectors[0].pixels: at most 1048576 pixels");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [1, 0, 0], "size": [1, -1], "pixels": [2, 2]})")),
              "scene.json: detectors[0].size[1]: must be > 0");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [1, 0, 0], "size": [1, 1], "pixels": [2, 2], "side": "left"})")),
              "scene.json: detectors[0].side: unknown side \"left\" (known: both, front, back)");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "plane", "name": "p", "center": [0, 0, 0], "normal": [0, 1, 0],)"
                                         R"( "up": [1, 0, 0], "size": [1, 1], "pixels": [2, 2], "absorbing": 1})")),
              "scene.json: detectors[0].absorbing: expected true or false, got number");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "shape_absorption", "name": "a", "pixels": [2, 2]})")),
              "scene.json: detectors[0]: unknown key \"pixels\" (valid keys: type, name, record)");
    EXPECT_EQ(sceneErrorOf(withDetectors(R"({"type": "shape_absorption", "name": "a", "record": -1})")),
              "scene.json: detectors[0].record: must be from 0 to 10000000");
}

TEST(DetectorReader, WriterRoundTripsEveryField) {
    const std::string text = withDetectors(
        R"({"type": "plane", "name": "screen", "center": [0.5, 0, 5], "normal": [0, 0, -1], "up": [0, 1, 0],)"
        R"( "size": [4, 2], "pixels": [8, 4], "side": "front", "absorbing": true, "record": 3},)"
        R"({"type": "far_field", "name": "sky", "look": [0, 0, 1], "up": [1, 1, 0], "projection": "equal_area",)"
        R"( "fov_deg": 360, "pixels": [20, 10]}, {"type": "shape_absorption", "name": "abs"})");
    const Scene scene = parseScene(text, "scene.json");
    const Scene again = parseScene(sceneToJson(scene), "saved.json");
    ASSERT_EQ(again.detectors.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const Detector& a = scene.detectors[i];
        const Detector& b = again.detectors[i];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.type, b.type);
        EXPECT_EQ(a.center, b.center);
        EXPECT_EQ(a.normal.vector(), b.normal.vector());
        EXPECT_EQ(a.up, b.up);
        EXPECT_EQ(a.size, b.size);
        EXPECT_EQ(a.pixels.nx, b.pixels.nx);
        EXPECT_EQ(a.pixels.ny, b.pixels.ny);
        EXPECT_EQ(a.side, b.side);
        EXPECT_EQ(a.absorbing, b.absorbing);
        EXPECT_EQ(a.look.vector(), b.look.vector());
        EXPECT_EQ(a.projection, b.projection);
        EXPECT_EQ(a.fovDeg, b.fovDeg);
        EXPECT_EQ(a.record, b.record);
    }
    EXPECT_EQ(again.detectors[0].side, DetectorSide::Front);
    EXPECT_TRUE(again.detectors[0].absorbing);
}

}  // namespace
}  // namespace dropscope
