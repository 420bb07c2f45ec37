// The document's edits: each checks everything first (throwing EditRefused), then commits one step.
#include "edit/SceneDocument.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Sphere.hpp"
#include "scene/GeneratorReader.hpp"
#include "scene/JsonPath.hpp"
#include "scene/MachineMemory.hpp"
#include "scene/SceneOverlaps.hpp"
#include "scene/WavelengthCoverage.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

namespace dropscope {

namespace {

// The smallest droplet radius, relative to the region's largest side or coordinate: the loader's
// limit for droplet_cloud (GeneratorReader.cpp), below which a droplet's own coordinates' rounding
// swamps it.
constexpr double kMinDropletRadiusRelative = 1e-9;

[[noreturn]] void refuse(const std::string& message) { throw EditRefused(message); }

// `value` to two significant digits, for messages ("0.31").
std::string roughly(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 2);
    return std::string(buffer, result.ptr);
}

// `text` followed by the quoted name, when there is one: `sphere "d1"`.
std::string withName(std::string text, const std::string& name) {
    if (!name.empty()) text.append(" ").append(jsonpath::quoted(name));
    return text;
}

double sphereVolume(double radius) { return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius; }

// Whether `after` is `before` moved: same medium and form, whatever the position.
bool isMove(const Shape& before, const Shape& after) {
    return before.mediumId() == after.mediumId() && before.sameFormAs(after);
}

void checkCloudSpec(const DropletCloudSpec& spec) {
    const Eigen::AlignedBox3d& region = spec.region;
    if (!region.min().allFinite() || !region.max().allFinite()) refuse("the region's corners must be finite");
    if (!withinCoordinateLimit(region.min()) || !withinCoordinateLimit(region.max())) {
        refuse("the region's corners are " + beyondCoordinateLimit());
    }
    for (Eigen::Index axis = 0; axis < 3; ++axis) {
        if (!(region.min()[axis] < region.max()[axis])) {
            refuse("the region's max must be > min on every axis (" + std::string(1, "xyz"[axis]) + ": max " +
                   jsonpath::number(region.max()[axis]) + " <= min " + jsonpath::number(region.min()[axis]) + ")");
        }
    }
    if (spec.count.has_value() == spec.volumeFraction.has_value()) refuse("give either a count or a volume fraction");
    if (spec.count && *spec.count > kMaxGeneratedDroplets) {
        refuse("a cloud has at most " + std::to_string(kMaxGeneratedDroplets) + " droplets");
    }
    if (spec.volumeFraction && !(*spec.volumeFraction > 0.0 && *spec.volumeFraction <= kMaxDropletVolumeFraction)) {
        refuse("the volume fraction must be > 0 and <= " + jsonpath::number(kMaxDropletVolumeFraction));
    }
}

// The loader's checks of drawn radii: the largest must fit in the region, the smallest must not vanish.
void checkRadii(const DropletCloudSpec& spec, const std::vector<double>& radii) {
    if (radii.size() > kMaxGeneratedDroplets) {
        refuse("the volume fraction needs more than " + std::to_string(kMaxGeneratedDroplets) +
               " droplets of this size; use larger radii or a smaller region");
    }
    const Eigen::Vector3d sides = spec.region.sizes();
    if (2.0 * radii.front() > sides.minCoeff()) {
        refuse("a droplet of radius " + roughly(radii.front()) + " does not fit in the region (its smallest side is " +
               jsonpath::number(sides.minCoeff()) + ")");
    }
    if (radii.back() < kMinDropletRadiusRelative * std::max(sides.maxCoeff(), largestCoordinate(spec.region))) {
        refuse("a droplet of radius " + roughly(radii.back()) + " is too small for the region");
    }
}

}  // namespace

// ---- checks ----

const Shape& SceneDocument::liveShape(ShapeId id) const {
    const Shape* s = octree_.shape(id);
    if (!s) refuse("there is no shape " + std::to_string(id));
    return *s;
}

std::unique_ptr<Shape> SceneDocument::shapeFor(const ShapeSpec& spec) const {
    checkMediumId(spec.medium);
    std::unique_ptr<Shape> shape;
    try {
        shape = makeShape(spec);
    } catch (const std::invalid_argument& error) {
        throw EditRefused(error.what());
    }
    if (const auto problem = shapeLimitProblem(*shape)) refuse(shapeTypeLabel(*shape) + ": " + *problem);
    return shape;
}

void SceneDocument::checkScale(const ScaleExtremes& added, const std::string& what, std::optional<ShapeId> replacing,
                               const Properties& properties) const {
    ScaleExtremes bound = seen_;
    bound.reach = std::max(bound.reach, added.reach);
    bound.feature = std::min(bound.feature, added.feature);
    for (const Source& source : properties.sources) bound.add(source);
    for (const Detector& detector : properties.detectors) bound.add(detector);
    if (bound.withinLimit()) return;
    ScaleExtremes exact = added;
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* live = octree_.shape(id);
        if (live && id != replacing) exact.add(*live);
    }
    for (const Source& source : properties.sources) exact.add(source);
    for (const Detector& detector : properties.detectors) exact.add(detector);
    if (exact.withinLimit()) return;
    // Name the edit's own part where it is the extreme one.
    const bool finest = exact.feature == added.feature;
    const bool farthest = exact.reach == added.reach;
    refuse((finest ? what : "the scene's smallest shape") + ": " +
           scaleLimitMessage(exact.feature, exact.reach, rest_.unit,
                             farthest ? "this " + what : "its farthest shape, source or detector"));
}

void SceneDocument::checkScale(const Shape& shape, std::optional<ShapeId> replacing) const {
    ScaleExtremes added;
    added.add(shape);
    checkScale(added, shapeTypeLabel(shape), replacing, properties());
}

void SceneDocument::checkName(const std::string& name, std::optional<ShapeId> owner) const {
    if (name.empty()) return;
    const std::optional<ShapeId> user = findShape(name);
    if (user && user != owner) {
        refuse("name " + jsonpath::quoted(name) + " is already used by shape " + std::to_string(*user));
    }
}

void SceneDocument::checkMediumId(MediumId id) const {
    if (id >= media().size()) {
        refuse("medium " + std::to_string(id) + " is not defined (" + std::to_string(media().size()) + " media)");
    }
}

Medium SceneDocument::checkedMedium(const Medium& medium, std::optional<MediumId> replacing) const {
    if (medium.name.empty()) refuse("a medium name must not be empty");
    for (MediumId id = 0; id < media().size(); ++id) {
        if (id != replacing && media()[id].name == medium.name) {
            refuse("medium name " + jsonpath::quoted(medium.name) + " is already used");
        }
    }
    if (medium.kappa && medium.sigma) refuse("give either kappa or sigma, not both");
    if (medium.kappaModel && !medium.kappa) refuse("a kappa model needs kappa");
    if (medium.sigmaModel && !medium.sigma) refuse("a sigma model needs sigma");
    Medium evaluated = medium;
    try {
        evaluateMediumAt(evaluated, wavelengthNm(), rest_.unitInMetres);  // the models' values at the scene wavelength
    } catch (const std::logic_error& error) {
        refuse(std::string(error.what()) + " (the scene wavelength)");
    }
    if (!(std::isfinite(evaluated.n) && evaluated.n > 0.0)) refuse("n must be finite and > 0");
    const auto nonNegative = [](const std::optional<double>& value) {
        return !value || (std::isfinite(*value) && *value >= 0.0);
    };
    if (!nonNegative(evaluated.kappa)) refuse("kappa must be finite and >= 0");
    if (!nonNegative(evaluated.sigma)) refuse("sigma must be finite and >= 0");
    return evaluated;
}

// The scene's overlap rule against the candidates the octree finds.
std::optional<std::string> SceneDocument::overlapOf(const Shape& shape, std::optional<ShapeId> ignore) const {
    for (const ShapeId other : octree_.overlapping(shape)) {
        if (other == ignore) continue;
        const Shape& existing = *octree_.shape(other);
        if (nestsInside(shape, existing) || nestsInside(existing, shape)) continue;
        return shapeTypeLabel(shape) + " would overlap shape " + std::to_string(other) + " (" +
               withName(shapeTypeLabel(existing), nameOf(other)) + ")";
    }
    return std::nullopt;
}

std::optional<std::string> SceneDocument::checkPlacement(const ShapeSpec& spec, std::optional<ShapeId> ignore) const {
    try {
        return overlapOf(*shapeFor(spec), ignore);
    } catch (const EditRefused& refusal) {
        return refusal.what();
    }
}

// ---- shapes ----

ShapeId SceneDocument::addShape(const ShapeSpec& spec, const std::string& name) {
    std::unique_ptr<Shape> shape = shapeFor(spec);
    checkName(name, std::nullopt);
    if (const auto overlap = overlapOf(*shape, std::nullopt)) refuse(*overlap);
    checkScale(*shape, std::nullopt);
    const auto id = static_cast<ShapeId>(octree_.slotCount());
    Step step;
    step.label = withName("add " + shapeTypeLabel(*shape), name);
    step.shapes.push_back({id, nullptr, std::move(shape), {}, name});
    commit(std::move(step));
    return id;
}

void SceneDocument::removeShape(ShapeId id) {
    const Shape& shape = liveShape(id);
    Step step;
    step.label = "delete " + shapeTitle(id);
    step.shapes.push_back({id, shape.clone(), nullptr, nameOf(id), {}});
    commit(std::move(step));
}

std::string SceneDocument::modifyLabel(ShapeId id, const Shape& before, const Shape& after) const {
    return (isMove(before, after) ? "move " : "edit ") + shapeTitle(id);
}

void SceneDocument::modifyShape(ShapeId id, const ShapeSpec& spec, bool mergeWithPrevious) {
    const Shape& current = liveShape(id);
    std::unique_ptr<Shape> shape = shapeFor(spec);
    if (const auto overlap = overlapOf(*shape, id)) refuse(*overlap);
    checkScale(*shape, id);
    const bool merge = mergeWithPrevious && redo_.empty() && !undo_.empty() && undo_.back().kind == StepKind::Modify &&
                       undo_.back().shapes.front().id == id;
    if (merge) {
        SlotChange& change = undo_.back().shapes.front();
        setSlot(id, shape->clone(), change.nameAfter);
        change.after = std::move(shape);
        undo_.back().label = modifyLabel(id, *change.before, *change.after);
        advance(StepKind::Modify);
        return;
    }
    Step step;
    step.kind = StepKind::Modify;
    step.label = modifyLabel(id, current, *shape);
    step.shapes.push_back({id, current.clone(), std::move(shape), nameOf(id), nameOf(id)});
    commit(std::move(step));
}

void SceneDocument::renameShape(ShapeId id, const std::string& name) {
    liveShape(id);
    checkName(name, id);
    Step step;
    step.label = "rename " + shapeTitle(id);
    step.renames.push_back({id, nameOf(id), name});
    commit(std::move(step));
}

std::vector<ShapeId> SceneDocument::generateCloud(const DropletCloudSpec& spec, MediumId medium) {
    checkMediumId(medium);
    checkCloudSpec(spec);
    const std::vector<double> radii = drawDropletRadii(spec, kMaxGeneratedDroplets);
    if (radii.empty()) return {};
    checkRadii(spec, radii);
    // The loader's limits, which the droplets would otherwise meet only when the saved scene is read again:
    // the largest droplet's volume, the smallest's size, and the scale of the scene with the cloud in it.
    if (!std::isfinite(sphereVolume(radii.front()))) {
        refuse("a droplet of radius " + roughly(radii.front()) + " has an infinite volume (docs/limits.md)");
    }
    if (radii.back() < kMinFeature) {
        refuse("a droplet of radius " + roughly(radii.back()) + " is below the limit " + roughly(kMinFeature) +
               " (docs/limits.md)");
    }
    ScaleExtremes cloud;
    cloud.reach = largestCoordinate(spec.region);
    cloud.feature = radii.back();
    checkScale(cloud, "the cloud", std::nullopt, properties());
    if (const auto problem = cloudMemoryProblem(shapeCount(), radii.size())) refuse(*problem);
    // Every current shape near the region is an obstacle, with the scene's nesting rule (the loader's
    // "explicit" shapes): droplets may lie inside a box or a sphere.
    std::vector<std::unique_ptr<Shape>> obstacles;
    for (const auto& shape : octree_.shapes()) {
        if (shape && shape->bounds().intersects(spec.region)) obstacles.push_back(shape->clone());
    }
    const std::vector<Droplet> droplets = placeDroplets(spec, radii, {obstacles, obstacles.size()});
    if (droplets.size() < radii.size()) {
        double volume = 0.0;
        for (const Droplet& d : droplets) volume += sphereVolume(d.radius);
        refuse("placed " + std::to_string(droplets.size()) + " of " + std::to_string(radii.size()) +
               " droplets before the region filled (volume fraction reached " + roughly(volume / spec.region.volume()) +
               "); lower the count or the volume fraction");
    }
    Step step;
    step.label = "generate " + std::to_string(droplets.size()) + " droplets";
    std::vector<ShapeId> ids;
    ids.reserve(droplets.size());
    for (const Droplet& droplet : droplets) {
        ids.push_back(static_cast<ShapeId>(octree_.slotCount() + ids.size()));
        auto sphere = std::make_unique<Sphere>(droplet.center, droplet.radius);
        sphere->setMediumId(medium);
        step.shapes.push_back({ids.back(), nullptr, std::move(sphere), {}, {}});
    }
    commit(std::move(step));
    return ids;
}

// ---- media, ambient, sources ----

void SceneDocument::checkWavelengths(const Properties& properties) const {
    const auto problem = findWavelengthCoverageProblem(properties.media, properties.sources, wavelengthNm());
    if (!problem) return;
    refuse("medium " + jsonpath::quoted(properties.media[problem->medium].name) + " " +
           opticalQuantityKey(problem->quantity) + ": " + problem->message + " (the light of source " +
           std::to_string(problem->source) + ")");
}

MediumId SceneDocument::addMedium(const Medium& medium) {
    Properties after = properties();
    after.media.push_back(checkedMedium(medium, std::nullopt));
    checkWavelengths(after);
    commitProperties("add medium " + jsonpath::quoted(medium.name), std::move(after));
    return static_cast<MediumId>(media().size() - 1);
}

void SceneDocument::setMedium(MediumId id, const Medium& medium) {
    checkMediumId(id);
    Properties after = properties();
    after.media[id] = checkedMedium(medium, id);
    checkWavelengths(after);
    commitProperties("edit medium " + jsonpath::quoted(media()[id].name), std::move(after));
}

void SceneDocument::setAmbient(MediumId id) {
    checkMediumId(id);
    Properties after = properties();
    after.ambient = id;
    commitProperties("set the ambient medium to " + jsonpath::quoted(media()[id].name), std::move(after));
}

void SceneDocument::setSources(std::vector<Source> sources, bool mergeWithPrevious) {
    for (std::size_t i = 0; i < sources.size(); ++i) {
        const Source& source = sources[i];
        const std::string which = "source " + std::to_string(i) + ": ";
        if (!source.origin.allFinite()) refuse(which + "origin must be finite");
        if (const auto problem = sourceLimitProblem(source)) refuse(which + *problem);
        if (source.type != SourceType::PointSource && !source.direction) {
            refuse(which + "direction must be a finite, non-zero vector");
        }
        if (source.type == SourceType::Beam && !(std::isfinite(source.radius) && source.radius > 0.0)) {
            refuse(which + "beam radius must be finite and > 0");
        }
        try {
            checkPolarisation(source);
            checkDivergence(source);
        } catch (const std::invalid_argument& error) {
            refuse(which + error.what());
        }
    }
    Properties after = properties();
    after.sources = std::move(sources);
    checkWavelengths(after);
    checkScale(ScaleExtremes{}, "the sources", std::nullopt, after);
    if (mergeWithPrevious && redo_.empty() && !undo_.empty() && undo_.back().kind == StepKind::Sources) {
        setProperties(after);
        undo_.back().after = std::move(after);
        advance(StepKind::Sources);
        return;
    }
    commitProperties("edit sources", std::move(after), StepKind::Sources);
}

}  // namespace dropscope
