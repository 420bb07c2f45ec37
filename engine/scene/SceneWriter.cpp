#include "scene/SceneWriter.hpp"

#include "geometry/GeneralShape.hpp"
#include "scene/JsonPath.hpp"
#include "scene/ShapeSpec.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <sstream>
#include <stdexcept>
#include <unordered_set>
#include <utility>

namespace dropscope {

namespace {

// Members keep their insertion order: "dropscope" first, media in id order.
using Json = nlohmann::ordered_json;

constexpr int kFormatVersion = 1;
constexpr std::string_view kIndent = "  ";

Json vector3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

[[noreturn]] void refuse(const std::string& message) { throw std::invalid_argument("writeScene: " + message); }

Json pairsJson(const std::vector<std::pair<double, double>>& pairs) {
    Json json = Json::array();
    for (const auto& [first, second] : pairs) json.push_back(Json::array({first, second}));
    return json;
}

Json spectralJson(const SpectralFunction& function) {
    switch (function.kind()) {
    case SpectralFunction::Kind::Constant: return function.constantValue();
    case SpectralFunction::Kind::Table: return {{"table_nm", pairsJson(function.tablePointsNm())}};
    case SpectralFunction::Kind::Cauchy: return {{"cauchy_um", function.coefficients()}};
    case SpectralFunction::Kind::Sellmeier:
        return {{"sellmeier_um", {{"B", function.coefficients()}, {"C", function.sellmeierC()}}}};
    case SpectralFunction::Kind::Builtin: {
        Json json = {{"builtin", materialName(function.material())}};
        if (function.material() == Material::Water && function.temperatureC() != 20.0) {
            json["temperature_c"] = function.temperatureC();
        }
        return json;
    }
    }
    return nullptr;
}

Json mediumJson(const Medium& medium) {
    Json json = Json::object();
    json["n"] = medium.nModel ? spectralJson(*medium.nModel) : Json(medium.n);
    if (medium.kappa) json["kappa"] = medium.kappaModel ? spectralJson(*medium.kappaModel) : Json(*medium.kappa);
    if (medium.sigma) json["sigma"] = medium.sigmaModel ? spectralJson(*medium.sigmaModel) : Json(*medium.sigma);
    return json;
}

Json spectrumJson(const Spectrum& spectrum) {
    const auto [lo, hi] = spectrum.boundsNm();
    switch (spectrum.kind()) {
    case Spectrum::Kind::Lines: return {{"lines_nm", pairsJson(spectrum.pointsNm())}};
    case Spectrum::Kind::Uniform: return {{"uniform_nm", Json::array({lo, hi})}};
    case Spectrum::Kind::Table: return {{"table_nm", pairsJson(spectrum.pointsNm())}};
    case Spectrum::Kind::Blackbody: return {{"blackbody_K", spectrum.kelvin()}, {"range_nm", Json::array({lo, hi})}};
    case Spectrum::Kind::Sun: return "sun";
    }
    return nullptr;
}

// values[offset ...] nested as `extents` says, row-major.
Json nested(const std::vector<double>& values, const std::vector<std::size_t>& extents, std::size_t level,
            std::size_t& offset) {
    if (level == extents.size()) return values[offset++];
    Json array = Json::array();
    for (std::size_t i = 0; i < extents[level]; ++i) array.push_back(nested(values, extents, level + 1, offset));
    return array;
}

Json matrixJson(const Eigen::Matrix3d& m) {
    Json rows = Json::array();
    for (Eigen::Index row = 0; row < 3; ++row) rows.push_back(vector3(m.row(row).transpose()));
    return rows;
}

// The preset's own parameters, then the transform as the matrix and translation it composed to (the
// steps it was written as are not kept; the placed shape is the same).
void writeGeneral(const GeneralShape& shape, Json& json) {
    json["preset"] = std::string(shape.presetName());
    for (const PresetParameter& parameter : shape.presetParameters()) {
        std::size_t offset = 0;
        json[parameter.key] = nested(parameter.values, parameter.extents, 0, offset);
    }
    const AffineTransform& transform = shape.transform();
    if (transform.isIdentity()) return;
    Json placed = Json::object();
    if (transform.matrix() != Eigen::Matrix3d::Identity()) placed["matrix"] = matrixJson(transform.matrix());
    if (transform.translation() != Eigen::Vector3d::Zero()) placed["translation"] = vector3(transform.translation());
    json["transform"] = placed;
}

Json shapeJson(const Shape& shape, const std::string& name, const std::vector<Medium>& media) {
    const ShapeSpec spec = describeShape(shape);
    Json json = Json::object();
    json["type"] = std::string(shape.typeName());
    if (!name.empty()) json["name"] = name;
    switch (spec.kind) {
    case ShapeKind::Sphere:
        json["center"] = vector3(spec.center);
        json["radius"] = spec.radius;
        break;
    case ShapeKind::Ellipsoid:
        json["center"] = vector3(spec.center);
        json["semi_axes"] = vector3(spec.semiAxes);
        if (spec.rotationAngleDeg != 0.0) {
            json["rotation"] = {{"axis", vector3(spec.rotationAxis)}, {"angle_deg", spec.rotationAngleDeg}};
        }
        break;
    case ShapeKind::Box:
        json["min"] = vector3(spec.boxMin);
        json["max"] = vector3(spec.boxMax);
        break;
    case ShapeKind::Parametric:
    case ShapeKind::Implicit: writeGeneral(static_cast<const GeneralShape&>(shape), json); break;
    }
    json["medium"] = media[shape.mediumId()].name;
    return json;
}

Json sourceJson(const Source& source) {
    Json json = Json::object();
    json["type"] = std::string(sourceTypeName(source.type));
    json["origin"] = vector3(source.origin);
    if (source.type != SourceType::PointSource) json["direction"] = vector3(source.direction.vector());
    if (source.type == SourceType::Beam) json["radius"] = source.radius;
    const SourcePolarisation& polarisation = source.polarisation;
    switch (polarisation.kind) {
    case PolarisationKind::Unpolarised: break;
    case PolarisationKind::Linear:
        json["polarisation"] = {{"linear_deg", polarisation.linearDeg}, {"reference", vector3(polarisation.reference)}};
        break;
    case PolarisationKind::Stokes: {
        const StokesVector& s = polarisation.stokes;
        json["polarisation"] = {{"stokes", Json::array({s[0], s[1], s[2], s[3]})},
                                {"reference", vector3(polarisation.reference)}};
        break;
    }
    }
    if (source.spectrum) json["spectrum"] = spectrumJson(*source.spectrum);
    if (source.divergenceDeg != 0.0) json["divergence_deg"] = source.divergenceDeg;
    return json;
}

Json detectorJson(const Detector& detector) {
    Json json = {{"type", std::string(detectorTypeName(detector.type))}, {"name", detector.name}};
    const auto pixels = [&] { return Json::array({detector.pixels.nx, detector.pixels.ny}); };
    if (detector.type == DetectorType::Plane) {
        json["center"] = vector3(detector.center);
        json["normal"] = vector3(detector.normal.vector());
        json["up"] = vector3(detector.up);
        json["size"] = Json::array({detector.size[0], detector.size[1]});
        json["pixels"] = pixels();
        if (detector.side != DetectorSide::Both) json["side"] = std::string(detectorSideName(detector.side));
        if (detector.absorbing) json["absorbing"] = true;
    } else if (detector.type == DetectorType::FarField) {
        json["look"] = vector3(detector.look.vector());
        json["up"] = vector3(detector.up);
        json["projection"] = std::string(projectionName(detector.projection));
        json["fov_deg"] = detector.fovDeg;
        json["pixels"] = pixels();
    }
    if (detector.record > 0) json["record"] = detector.record;
    return json;
}

Json viewJson(const SceneView& view) {
    return {{"eye", vector3(view.eye)},
            {"target", vector3(view.target)},
            {"up", vector3(view.up.vector())},
            {"fov_deg", view.fovDeg}};
}

// Names that would make the file unreadable, or change what it means, are refused here rather than
// by the loader later.
void checkWritable(const Scene& scene) {
    std::unordered_set<std::string> names;
    for (const Medium& medium : scene.media) {
        if (medium.name.empty()) refuse("a medium has an empty name");
        if (!names.insert(medium.name).second) refuse("medium name " + jsonpath::quoted(medium.name) + " is repeated");
    }
    if (scene.ambient >= scene.media.size()) {
        refuse("ambient medium " + std::to_string(scene.ambient) + " is not defined");
    }
    names.clear();
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        if (!scene.shapes[id]) refuse("shape " + std::to_string(id) + " is null");
        if (scene.shapes[id]->mediumId() >= scene.media.size()) {
            refuse("shape " + std::to_string(id) + " has medium " + std::to_string(scene.shapes[id]->mediumId()) +
                   ", which is not defined");
        }
        const std::string& name = id < scene.shapeNames.size() ? scene.shapeNames[id] : std::string();
        if (!name.empty() && !names.insert(name).second) {
            refuse("shape name " + jsonpath::quoted(name) + " is repeated");
        }
    }
    names.clear();
    for (const Detector& detector : scene.detectors) {
        try {
            checkDetector(detector);
        } catch (const std::invalid_argument& error) {
            refuse("detector " + jsonpath::quoted(detector.name) + ": " + error.what());
        }
        if (!names.insert(detector.name).second) {
            refuse("detector name " + jsonpath::quoted(detector.name) + " is repeated");
        }
    }
}

// `value` on one line, with a space after each comma and colon.
void writeInline(std::ostream& out, const Json& value) {
    if (value.is_object()) {
        out << '{';
        const char* separator = "";
        for (const auto& [key, member] : value.items()) {
            out << separator << Json(key).dump() << ": ";
            writeInline(out, member);
            separator = ", ";
        }
        out << '}';
    } else if (value.is_array()) {
        out << '[';
        const char* separator = "";
        for (const Json& element : value) {
            out << separator;
            writeInline(out, element);
            separator = ", ";
        }
        out << ']';
    } else {
        out << value.dump();
    }
}

// A top-level member. A block (media, shapes, sources) puts each of its members or elements on a line
// of its own; anything else stays on the member's line.
struct Member {
    std::string key;
    Json value;
    bool block = false;
};

void writeMember(std::ostream& out, const Member& member) {
    out << kIndent << Json(member.key).dump() << ": ";
    if (!member.block || member.value.empty()) {
        writeInline(out, member.value);
        return;
    }
    const bool object = member.value.is_object();
    out << (object ? "{" : "[");
    const char* separator = "\n";
    for (const auto& [key, element] : member.value.items()) {
        out << separator << kIndent << kIndent;
        if (object) out << Json(key).dump() << ": ";
        writeInline(out, element);
        separator = ",\n";
    }
    out << '\n' << kIndent << (object ? "}" : "]");
}

}  // namespace

void writeScene(const Scene& scene, std::ostream& out) {
    checkWritable(scene);
    Json media = Json::object();
    for (const Medium& medium : scene.media) media[medium.name] = mediumJson(medium);
    Json shapes = Json::array();
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const std::string& name = id < scene.shapeNames.size() ? scene.shapeNames[id] : std::string();
        shapes.push_back(shapeJson(*scene.shapes[id], name, scene.media));
    }
    Json sources = Json::array();
    for (const Source& source : scene.sources) sources.push_back(sourceJson(source));

    std::vector<Member> members{
        {"dropscope", kFormatVersion},
        {"unit", scene.unit},
        {"wavelength_nm", scene.wavelengthNm},
        {"ambient", scene.media[scene.ambient].name},
        {"media", std::move(media), true},
        {"shapes", std::move(shapes), true},
        {"sources", std::move(sources), true},
        {"octree", {{"max_depth", scene.octree.maxDepth}, {"max_shapes_per_leaf", scene.octree.maxShapesPerLeaf}}},
    };
    if (scene.view) members.push_back({"view", viewJson(*scene.view)});
    if (!scene.detectors.empty()) {
        Json detectors = Json::array();
        for (const Detector& detector : scene.detectors) detectors.push_back(detectorJson(detector));
        members.push_back({"detectors", std::move(detectors), true});
    }

    out << "{\n";
    const char* separator = "";
    for (const Member& member : members) {
        out << separator;
        writeMember(out, member);
        separator = ",\n";
    }
    out << "\n}\n";
}

std::string sceneToJson(const Scene& scene) {
    std::ostringstream out;
    writeScene(scene, out);
    return out.str();
}

}  // namespace dropscope
