// The document's state, its history (commit, undo, redo) and how a step is applied to the octree.
// The edits and their checks are in SceneDocumentEdits.cpp.
#include "edit/SceneDocument.hpp"

#include "geometry/GeneralShape.hpp"
#include "scene/JsonPath.hpp"

#include <algorithm>

namespace dropscope {

namespace {

// A step changing more shapes than this (a droplet cloud) rebuilds the octree once instead of
// thawing and freezing it per shape: both cost O(N), the rebuild a few times more than one insert.
constexpr std::size_t kMaxIncrementalChanges = 8;

std::unique_ptr<Shape> cloneOf(const std::unique_ptr<Shape>& shape) { return shape ? shape->clone() : nullptr; }

}  // namespace

SceneDocument::SceneDocument(Scene scene)
    : octree_(std::move(scene.shapes), scene.octree), names_(std::move(scene.shapeNames)), rest_(std::move(scene)) {
    rest_.shapes.clear();
    rest_.shapeNames.clear();
    rest_.explicitShapeCount = 0;
    names_.resize(octree_.slotCount());
    for (ShapeId id = 0; id < names_.size(); ++id) {
        if (!octree_.shape(id)) names_[id].clear();
        if (!names_[id].empty()) nameIndex_.emplace(names_[id], id);
        if (const Shape* s = octree_.shape(id)) seen_.add(*s);
    }
    for (const Source& source : rest_.sources) seen_.add(source);
    for (const Detector& detector : rest_.detectors) seen_.add(detector);
}

const std::string& SceneDocument::nameOf(ShapeId id) const {
    static const std::string unnamed;
    return id < names_.size() ? names_[id] : unnamed;
}

std::optional<ShapeId> SceneDocument::findShape(const std::string& name) const {
    const auto found = nameIndex_.find(name);
    if (found == nameIndex_.end()) return std::nullopt;
    return found->second;
}

std::string SceneDocument::shapeTitle(ShapeId id) const {
    const Shape* s = shape(id);
    std::string title = s ? shapeTypeLabel(*s) : "shape";
    const std::string& name = nameOf(id);
    return title + " " + (name.empty() ? std::to_string(id) : jsonpath::quoted(name));
}

void SceneDocument::advance(StepKind kind) {
    ++revision_;
    if (kind != StepKind::Sources) ++revisionBesidesSources_;
}

void SceneDocument::commit(Step step) {
    apply(step, true);
    const StepKind kind = step.kind;
    undo_.push_back(std::move(step));
    if (undo_.size() > kMaxUndoSteps) undo_.pop_front();
    redo_.clear();
    advance(kind);
}

void SceneDocument::undo() {
    if (undo_.empty()) return;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    apply(step, false);
    const StepKind kind = step.kind;
    redo_.push_back(std::move(step));
    advance(kind);
}

void SceneDocument::redo() {
    if (redo_.empty()) return;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    apply(step, true);
    const StepKind kind = step.kind;
    undo_.push_back(std::move(step));
    advance(kind);
}

void SceneDocument::apply(const Step& step, bool forward) {
    applyShapeChanges(step.shapes, forward);
    for (const Rename& rename : step.renames) setName(rename.id, forward ? rename.after : rename.before);
    if (step.after) setProperties(forward ? *step.after : *step.before);
}

// Forwards in order, backwards in reverse order, each slot set to a copy of its target (the step keeps
// its own for the next undo or redo).
void SceneDocument::applyShapeChanges(const std::vector<SlotChange>& changes, bool forward) {
    if (changes.size() <= kMaxIncrementalChanges) {
        const auto setTo = [&](const SlotChange& change) {
            setSlot(change.id, cloneOf(forward ? change.after : change.before),
                    forward ? change.nameAfter : change.nameBefore);
        };
        if (forward) {
            std::for_each(changes.begin(), changes.end(), setTo);
        } else {
            std::for_each(changes.rbegin(), changes.rend(), setTo);
        }
        return;
    }
    std::size_t slots = octree_.slotCount();
    for (const SlotChange& change : changes) slots = std::max<std::size_t>(slots, change.id + std::size_t{1});
    std::vector<std::unique_ptr<Shape>> shapes(slots);
    for (std::size_t id = 0; id < octree_.slotCount(); ++id) shapes[id] = cloneOf(octree_.shapes()[id]);
    for (const SlotChange& change : changes) {
        shapes[change.id] = cloneOf(forward ? change.after : change.before);
        if (shapes[change.id]) seen_.add(*shapes[change.id]);
        setName(change.id, forward ? change.nameAfter : change.nameBefore);
    }
    octree_ = Octree(std::move(shapes), rest_.octree);
}

void SceneDocument::setSlot(ShapeId id, std::unique_ptr<Shape> shape, const std::string& name) {
    if (octree_.shape(id)) octree_.remove(id);
    setName(id, shape ? name : std::string());
    if (!shape) return;
    seen_.add(*shape);
    if (id == octree_.slotCount()) {
        octree_.insert(std::move(shape));
    } else {
        octree_.insertAt(id, std::move(shape));
    }
}

void SceneDocument::setName(ShapeId id, const std::string& name) {
    if (names_.size() <= id) names_.resize(id + std::size_t{1});
    const auto indexed = nameIndex_.find(names_[id]);
    if (indexed != nameIndex_.end() && indexed->second == id) nameIndex_.erase(indexed);
    names_[id] = name;
    if (!name.empty()) nameIndex_[name] = id;
}

void SceneDocument::setProperties(const Properties& properties) {
    rest_.media = properties.media;
    rest_.ambient = properties.ambient;
    rest_.sources = properties.sources;
    rest_.detectors = properties.detectors;
    for (const Source& source : rest_.sources) seen_.add(source);
    for (const Detector& detector : rest_.detectors) seen_.add(detector);
}

void SceneDocument::commitProperties(std::string label, Properties after, StepKind kind) {
    Step step;
    step.label = std::move(label);
    step.kind = kind;
    step.before = properties();
    step.after = std::move(after);
    commit(std::move(step));
}

Scene SceneDocument::toScene(std::vector<ShapeId>* slotOfShape) const {
    Scene scene;
    scene.origin = rest_.origin;
    scene.formatVersion = rest_.formatVersion;
    scene.unit = rest_.unit;
    scene.unitInMetres = rest_.unitInMetres;
    scene.wavelengthNm = rest_.wavelengthNm;
    scene.ambient = rest_.ambient;
    scene.media = rest_.media;
    scene.sources = rest_.sources;
    scene.detectors = rest_.detectors;
    scene.octree = rest_.octree;
    scene.view = rest_.view;
    scene.shapes.reserve(octree_.shapeCount());
    scene.shapeNames.reserve(octree_.shapeCount());
    if (slotOfShape) {
        slotOfShape->clear();
        slotOfShape->reserve(octree_.shapeCount());
    }
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* s = octree_.shape(id);
        if (!s) continue;
        scene.shapes.push_back(s->clone());
        scene.shapeNames.push_back(names_[id]);
        if (slotOfShape) slotOfShape->push_back(id);
    }
    scene.explicitShapeCount = scene.shapes.size();
    return scene;
}

}  // namespace dropscope
