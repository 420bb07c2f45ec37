#include "cli/InspectReport.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/implicit/ImplicitShape.hpp"

#include <nlohmann/json.hpp>

#include <ostream>

namespace dropscope {

namespace {

using Json = nlohmann::ordered_json;

Json vectorJson(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json boundsJson(const Eigen::AlignedBox3d& bounds) {
    return {{"min", vectorJson(bounds.min())}, {"max", vectorJson(bounds.max())}};
}

Json optionalJson(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

Json mediaJson(const Scene& scene) {
    Json media = Json::array();
    for (std::size_t id = 0; id < scene.media.size(); ++id) {
        const Medium& medium = scene.media[id];
        Json dispersion = nullptr;
        if (medium.dispersive()) {
            Json values = Json::array();
            for (const auto& [wavelength, optics] : dispersionSamples(scene, medium)) {
                values.push_back({{"wavelength_nm", wavelength},
                                  {"n", optics ? Json(optics->n) : Json(nullptr)},
                                  {"absorption_per_unit", optics ? Json(optics->absorptionPerUnit) : Json(nullptr)}});
            }
            dispersion = {{"n", spectralModelText(medium.nModel)},
                          {"kappa", spectralModelText(medium.kappaModel)},
                          {"sigma", spectralModelText(medium.sigmaModel)},
                          {"values", values}};
        }
        media.push_back({{"id", id},
                         {"name", medium.name},
                         {"n", medium.n},
                         {"kappa", optionalJson(medium.kappa)},
                         {"sigma", optionalJson(medium.sigma)},
                         {"absorption_per_unit", medium.absorptionPerUnit},
                         {"dispersion", dispersion}});
    }
    return media;
}

Json shapesJson(const Scene& scene) {
    Json shapes = Json::array();
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const Shape& shape = *scene.shapes[id];
        const std::string& name = scene.shapeNames[id];
        Json entry = {{"id", id},
                      {"type", shape.typeName()},
                      {"name", name.empty() ? Json(nullptr) : Json(name)},
                      {"medium", scene.mediumOf(shape).name},
                      {"medium_id", shape.mediumId()},
                      {"bounds", boundsJson(shape.bounds())},
                      {"volume", shape.volume()},
                      {"surface_area", shape.surfaceArea()}};
        if (const GeneralShape* general = asGeneralShape(shape)) entry["preset"] = std::string(general->presetName());
        // Implicit volumes and areas are numerical integrals to ~1e-6: their estimated absolute errors.
        if (const auto* implicit = dynamic_cast<const ImplicitShape*>(&shape)) {
            entry["volume_error"] = implicit->volumeEstimate().errorEstimate;
            entry["surface_area_error"] = implicit->areaEstimate().errorEstimate;
        }
        shapes.push_back(std::move(entry));
    }
    return shapes;
}

// As the scene file gives it (docs/scene-format.md, "Polarisation").
Json polarisationJson(const SourcePolarisation& polarisation) {
    switch (polarisation.kind) {
    case PolarisationKind::Unpolarised: return "unpolarised";
    case PolarisationKind::Linear:
        return {{"linear_deg", polarisation.linearDeg}, {"reference", vectorJson(polarisation.reference)}};
    case PolarisationKind::Stokes: {
        const StokesVector& s = polarisation.stokes;
        return {{"stokes", Json::array({s[0], s[1], s[2], s[3]})}, {"reference", vectorJson(polarisation.reference)}};
    }
    }
    return nullptr;
}

// null for the scene's line; else the kind and the range (and a blackbody's temperature).
Json spectrumJson(const Source& source) {
    if (!source.spectrum) return nullptr;
    const auto [lo, hi] = source.spectrum->rangeNm();
    Json json = {{"kind", spectrumKindName(source.spectrum->kind())}, {"lo_nm", lo}, {"hi_nm", hi}};
    if (source.spectrum->kind() == Spectrum::Kind::Lines) {
        Json lines = Json::array();
        for (const auto& [wavelength, weight] : source.spectrum->pointsNm()) lines.push_back({wavelength, weight});
        json["lines_nm"] = lines;
    }
    if (source.spectrum->kind() == Spectrum::Kind::Blackbody || source.spectrum->kind() == Spectrum::Kind::Sun) {
        json["kelvin"] = source.spectrum->kelvin();
    }
    return json;
}

Json sourcesJson(const Scene& scene) {
    Json sources = Json::array();
    for (std::size_t id = 0; id < scene.sources.size(); ++id) {
        const Source& source = scene.sources[id];
        sources.push_back(
            {{"id", id},
             {"type", sourceTypeName(source.type)},
             {"origin", vectorJson(source.origin)},
             {"direction", source.type == SourceType::PointSource ? Json(nullptr) : vectorJson(source.direction)},
             {"radius", source.type == SourceType::Beam ? Json(source.radius) : Json(nullptr)},
             {"polarisation", polarisationJson(source.polarisation)},
             {"spectrum", spectrumJson(source)},
             {"divergence_deg", source.divergenceDeg}});
    }
    return sources;
}

Json totalsJson(const Scene& scene, const SceneSummary& summary) {
    return {{"shapes", scene.shapes.size()},
            {"shapes_by_type", summary.shapesByType},
            {"volume", summary.totalVolume},
            {"surface_area", summary.totalSurfaceArea},
            {"bounds", summary.bounds ? boundsJson(*summary.bounds) : Json(nullptr)}};
}

Json octreeJson(const OctreeSummary& octree) {
    Json levels = Json::array();
    for (const LevelStatistics& level : octree.levels) {
        levels.push_back({{"level", level.level},
                          {"cells", level.cells},
                          {"leaves", level.leaves},
                          {"shapes_stored", level.shapesStored},
                          {"bytes", level.bytes},
                          {"shapes_per_leaf", level.shapesPerLeaf}});
    }
    return {{"max_depth", octree.settings.maxDepth},
            {"max_shapes_per_leaf", octree.settings.maxShapesPerLeaf},
            {"root", boundsJson(octree.root)},
            {"margin", octree.margin},
            {"bytes", octree.bytes},
            {"levels", levels}};
}

}  // namespace

void writeInspectJson(const Scene& scene, const SceneSummary& summary, std::ostream& out) {
    const Json document = {{"scene", scene.origin},
                           {"format", scene.formatVersion},
                           {"unit", scene.unit},
                           {"unit_in_metres", scene.unitInMetres},
                           {"wavelength_nm", scene.wavelengthNm},
                           {"wavelength_in_unit", scene.wavelengthInSceneUnits()},
                           {"ambient", scene.media.at(scene.ambient).name},
                           {"media", mediaJson(scene)},
                           {"shapes", shapesJson(scene)},
                           {"sources", sourcesJson(scene)},
                           {"totals", totalsJson(scene, summary)},
                           {"octree", octreeJson(summary.octree)}};
    out << document.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

}  // namespace dropscope
