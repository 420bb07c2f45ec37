#include "scene/DetectorReader.hpp"

#include "scene/JsonPath.hpp"

#include <limits>
#include <set>

namespace dropscope {

namespace {

PixelGrid readPixels(const JsonReader& json) {
    const std::vector<JsonReader> counts = json.fixedArray(2, "[nx, ny], two whole numbers");
    PixelGrid grid;
    int* const axes[2] = {&grid.nx, &grid.ny};
    for (std::size_t k = 0; k < 2; ++k) {
        const std::int64_t count = counts[k].integer();
        if (count < 1 || count > static_cast<std::int64_t>(kMaxDetectorPixels)) {
            counts[k].fail("must be from 1 to " + std::to_string(kMaxDetectorPixels));
        }
        *axes[k] = static_cast<int>(count);
    }
    if (grid.count() > kMaxDetectorPixels) json.fail("at most " + std::to_string(kMaxDetectorPixels) + " pixels");
    return grid;
}

DetectorSide readSide(const JsonReader& json) {
    const std::string side = json.string();
    if (side == "both") return DetectorSide::Both;
    if (side == "front") return DetectorSide::Front;
    if (side == "back") return DetectorSide::Back;
    json.fail("unknown side " + jsonpath::quoted(side) + " (known: both, front, back)");
}

FarFieldProjection readProjection(const JsonReader& json) {
    const std::string projection = json.string();
    if (projection == "equidistant") return FarFieldProjection::Equidistant;
    if (projection == "equal_area") return FarFieldProjection::EqualArea;
    if (projection == "perspective") return FarFieldProjection::Perspective;
    json.fail("unknown projection " + jsonpath::quoted(projection) + " (known: equidistant, equal_area, perspective)");
}

Detector readDetector(const JsonReader& json) {
    json.expectObject();
    const JsonReader typeJson = json.member("type");
    const std::string type = typeJson.string();
    Detector detector;
    if (type == "plane") {
        json.expectKeys({"type", "name", "center", "normal", "up", "size", "pixels", "side", "absorbing", "record"});
        detector.type = DetectorType::Plane;
    } else if (type == "far_field") {
        json.expectKeys({"type", "name", "look", "up", "projection", "fov_deg", "pixels", "record"});
        detector.type = DetectorType::FarField;
    } else if (type == "shape_absorption") {
        json.expectKeys({"type", "name", "record"});
        detector.type = DetectorType::ShapeAbsorption;
    } else {
        typeJson.fail("unknown detector type " + jsonpath::quoted(type) +
                      " (known: plane, far_field, shape_absorption)");
    }
    const JsonReader name = json.member("name");
    detector.name = name.string();
    if (!isDetectorName(detector.name)) {
        name.fail("a detector name is 1 to " + std::to_string(kMaxDetectorNameLength) +
                  " letters, digits, '_' or '-', got " + jsonpath::quoted(detector.name));
    }
    if (const auto record = json.optionalMember("record")) {
        const std::int64_t count = record->integer();
        if (count < 0 || static_cast<std::uint64_t>(count) > kMaxDetectorRecords) {
            record->fail("must be from 0 to " + std::to_string(kMaxDetectorRecords));
        }
        detector.record = static_cast<std::uint64_t>(count);
    }
    if (detector.type == DetectorType::ShapeAbsorption) return detector;
    detector.pixels = readPixels(json.member("pixels"));
    const JsonReader up = json.member("up");
    detector.up = up.vector3();
    if (detector.type == DetectorType::Plane) {
        detector.center = json.member("center").vector3();
        detector.normal = json.member("normal").direction();
        const JsonReader size = json.member("size");
        const std::vector<JsonReader> sides = size.fixedArray(2, "[w, h], two numbers");
        detector.size = {sides[0].positive(), sides[1].positive()};
        if (const auto side = json.optionalMember("side")) detector.side = readSide(*side);
        if (const auto absorbing = json.optionalMember("absorbing")) detector.absorbing = absorbing->boolean();
        up.construct([&] { planeFrame(detector); });
        return detector;
    }
    detector.look = json.member("look").direction();
    if (const auto projection = json.optionalMember("projection")) detector.projection = readProjection(*projection);
    const JsonReader fov = json.member("fov_deg");
    detector.fovDeg = fov.positive();
    up.construct([&] { FarFieldCamera{detector}; });
    fov.construct([&] { checkDetector(detector); });
    return detector;
}

}  // namespace

std::vector<Detector> readDetectors(const JsonReader& json) {
    std::vector<Detector> detectors;
    std::set<std::string> names;
    for (const JsonReader& element : json.elements()) {
        detectors.push_back(readDetector(element));
        if (!names.insert(detectors.back().name).second) {
            element.member("name").fail("another detector is already named " + jsonpath::quoted(detectors.back().name));
        }
    }
    return detectors;
}

}  // namespace dropscope
