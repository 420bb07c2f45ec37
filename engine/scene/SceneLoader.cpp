#include "scene/SceneLoader.hpp"

#include "scene/DetectorReader.hpp"
#include "scene/GeneratorReader.hpp"
#include "scene/JsonDocument.hpp"
#include "scene/JsonPath.hpp"
#include "scene/JsonReader.hpp"
#include "scene/MediaReader.hpp"
#include "scene/SceneLimits.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/ShapeReader.hpp"
#include "scene/SourceReader.hpp"
#include "scene/WavelengthCoverage.hpp"

#include <array>
#include <cerrno>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

namespace dropscope {

namespace {

constexpr std::int64_t kFormatVersion = 1;
// Deepest octree the scene may ask for (Octree accepts 0..30).
constexpr std::int64_t kMaxOctreeDepth = 30;

struct LengthUnit {
    std::string_view name;
    double metres;
};
constexpr std::array<LengthUnit, 5> kLengthUnits{{{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}}};

// The ambient medium when "ambient" is left out (n = 1), unless the file defines a medium of that name.
constexpr std::string_view kDefaultAmbientName = "vacuum";

void readFormatVersion(const JsonReader& root, Scene& scene) {
    const JsonReader version = root.member("dropscope");
    const std::int64_t value = version.integer();
    if (value != kFormatVersion) {
        version.fail("unsupported format version " + std::to_string(value) + " (this program reads version " +
                     std::to_string(kFormatVersion) + ")");
    }
    scene.formatVersion = static_cast<int>(value);
}

void readUnit(const JsonReader& root, Scene& scene) {
    const auto unit = root.optionalMember("unit");
    if (!unit) return;
    const std::string name = unit->string();
    for (const LengthUnit& known : kLengthUnits) {
        if (known.name == name) {
            scene.unit = name;
            scene.unitInMetres = known.metres;
            return;
        }
    }
    unit->fail("unknown unit " + jsonpath::quoted(name) + " (known: m, cm, mm, um, nm)");
}

void readAmbient(const JsonReader& root, Scene& scene) {
    if (const auto ambient = root.optionalMember("ambient")) {
        scene.ambient = readMediumName(*ambient, scene.media);
        return;
    }
    if (const auto defined = scene.findMedium(std::string(kDefaultAmbientName))) {
        scene.ambient = *defined;
        return;
    }
    Medium vacuum;
    vacuum.name = kDefaultAmbientName;
    scene.ambient = static_cast<MediumId>(scene.media.size());
    scene.media.push_back(std::move(vacuum));
}

void readShapes(const JsonReader& shapes, Scene& scene) {
    checkImplicitLoadTime(shapes);
    BaseCache cache;
    for (const JsonReader& json : shapes.elements()) {
        NamedShape shape = readShape(json, scene.media, cache);
        // Before anything uses its bounds: the pairwise checks and the octree need finite ones.
        if (const auto problem = shapeLimitProblem(*shape.shape)) json.fail(*problem);
        for (std::size_t other = 0; other < scene.shapeNames.size() && !shape.name.empty(); ++other) {
            if (scene.shapeNames[other] == shape.name) {
                json.member("name").fail("name " + jsonpath::quoted(shape.name) + " is already used by " +
                                         jsonpath::element("shapes", other));
            }
        }
        scene.shapes.push_back(std::move(shape.shape));
        scene.shapeNames.push_back(std::move(shape.name));
    }
}

// {"max_depth": 0..30, "max_shapes_per_leaf": >= 1}, both optional.
void readOctreeSettings(const JsonReader& json, Scene& scene) {
    json.expectKeys({"max_depth", "max_shapes_per_leaf"});
    if (const auto depth = json.optionalMember("max_depth")) {
        const std::int64_t value = depth->integer();
        if (value < 0 || value > kMaxOctreeDepth) {
            depth->fail("must be in 0.." + std::to_string(kMaxOctreeDepth) + ", got " + std::to_string(value));
        }
        scene.octree.maxDepth = static_cast<int>(value);
    }
    if (const auto perLeaf = json.optionalMember("max_shapes_per_leaf")) {
        const std::int64_t value = perLeaf->integer();
        if (value < 1) perLeaf->fail("must be >= 1, got " + std::to_string(value));
        if (value > std::numeric_limits<int>::max()) {
            perLeaf->fail("must be <= " + std::to_string(std::numeric_limits<int>::max()) + ", got " +
                          std::to_string(value));
        }
        scene.octree.maxShapesPerLeaf = static_cast<int>(value);
    }
}

// {"eye": [..], "target": [..], "up": [..] (optional), "fov_deg": (optional, 0 < f < 180)}.
void readView(const JsonReader& json, Scene& scene) {
    json.expectKeys({"eye", "target", "up", "fov_deg"});
    SceneView view;
    view.eye = json.member("eye").vector3();
    view.target = json.member("target").vector3();
    for (const auto& [point, key] : {std::pair{view.eye, "eye"}, std::pair{view.target, "target"}}) {
        if (!withinCoordinateLimit(point)) json.member(key).fail(beyondCoordinateLimit());
    }
    if ((view.eye - view.target).norm() == 0.0) json.member("target").fail("must differ from eye");
    if (const auto up = json.optionalMember("up")) {
        view.up = up->direction();
        if ((view.target - view.eye).cross(view.up.vector()).norm() == 0.0)
            up->fail("must not be parallel to target - eye");
    }
    if (const auto fov = json.optionalMember("fov_deg")) {
        view.fovDeg = fov->positive();
        if (view.fovDeg >= 180.0) fov->fail("must be < 180, got " + jsonpath::number(view.fovDeg));
    }
    scene.view = view;
}

// Every dispersive medium must be defined at every wavelength a source emits.
void checkMediaCoverSpectra(const JsonReader& root, const Scene& scene) {
    const auto problem = findWavelengthCoverageProblem(scene.media, scene.sources, scene.wavelengthNm);
    if (!problem) return;
    const JsonReader model =
        root.member("media").member(scene.media[problem->medium].name).member(opticalQuantityKey(problem->quantity));
    const bool ownSpectrum = scene.sources[problem->source].spectrum.has_value();
    model.fail(problem->message + " (the light of sources[" + std::to_string(problem->source) + "]" +
               (ownSpectrum ? ".spectrum" : ", at the scene's \"wavelength_nm\"") + ")");
}

}  // namespace

Scene parseScene(std::string_view jsonText, const std::string& origin) {
    const Json document = parseJsonDocument(jsonText, origin);
    const JsonReader root(document, "", origin);
    Scene scene;
    scene.origin = origin;
    readFormatVersion(root, scene);
    root.expectKeys({"dropscope", "unit", "wavelength_nm", "ambient", "media", "shapes", "sources", "octree",
                     "generators", "view", "detectors"});
    readUnit(root, scene);
    if (const auto wavelength = root.optionalMember("wavelength_nm")) scene.wavelengthNm = wavelength->positive();
    if (const auto media = root.optionalMember("media")) {
        scene.media = readMedia(*media, scene.wavelengthNm, scene.unitInMetres);
    }
    readAmbient(root, scene);
    if (const auto shapes = root.optionalMember("shapes")) readShapes(*shapes, scene);
    if (const auto sources = root.optionalMember("sources")) {
        for (const JsonReader& json : sources->elements()) scene.sources.push_back(readSource(json));
    }
    checkMediaCoverSpectra(root, scene);
    if (const auto octree = root.optionalMember("octree")) readOctreeSettings(*octree, scene);
    if (const auto view = root.optionalMember("view")) readView(*view, scene);
    if (const auto detectors = root.optionalMember("detectors")) scene.detectors = readDetectors(*detectors);
    checkSourceAndDetectorLimits(scene);
    // Only the explicit shapes need the pairwise check; generated droplets avoid everything by construction.
    checkShapesDisjoint(scene);
    scene.explicitShapeCount = scene.shapes.size();
    // Before and after the generators: a scale problem of the explicit shapes is said before placing up to
    // 1e7 droplets.
    checkSceneScale(scene);
    if (const auto generators = root.optionalMember("generators")) {
        readGenerators(*generators, scene);
        checkSceneScale(scene);
    }
    return scene;
}

Scene loadScene(const std::filesystem::path& file) { return parseScene(readJsonFileText(file), file.string()); }

}  // namespace dropscope
