#include "scene/SourceReader.hpp"

#include "scene/JsonPath.hpp"

namespace dropscope {

Source readSource(const JsonReader& json) {
    const JsonReader typeJson = json.member("type");
    const std::string type = typeJson.string();
    Source source;
    if (type == "beam") {
        json.expectKeys({"type", "origin", "direction", "radius"});
        source.type = SourceType::Beam;
    } else if (type == "ray") {
        json.expectKeys({"type", "origin", "direction"});
        source.type = SourceType::Ray;
    } else if (type == "point") {
        json.expectKeys({"type", "origin"});
        source.type = SourceType::PointSource;
    } else {
        typeJson.fail("unknown source type " + jsonpath::quoted(type) + " (known: beam, ray, point)");
    }
    source.origin = json.member("origin").vector3();
    if (source.type != SourceType::PointSource) source.direction = json.member("direction").direction();
    if (source.type == SourceType::Beam) source.radius = json.member("radius").positive();
    return source;
}

}  // namespace dropscope
