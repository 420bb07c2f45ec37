#pragma once

#include "scene/DropletCloud.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLimits.hpp"
#include "scene/ShapeSpec.hpp"
#include "tree/Octree.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace dropscope {

// An edit the document refuses; what() is one line for the user ("radius must be > 0", "sphere would
// overlap shape 12 (sphere \"d1\")"). A refused edit changes nothing.
class EditRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The editable scene the GUI holds: the shapes in an Octree kept up to date edit by edit, the media,
// ambient medium, sources and the rest of a Scene, and an undo history.
//
// Shape ids are octree slots: at load, the scene's shape ids; a new shape takes a new slot; removing
// one leaves its slot empty, and ids never change, so undoing a removal puts the shape back under the
// same id (Octree::insertAt). Shapes follow the scene file's overlap rule (docs/scene-format.md,
// "Overlaps"): they may touch or nest (anything in a box, a sphere in a sphere), never partly overlap.
//
// Every edit is one undoable step, checked before anything changes. revision() increases on every
// change, undo and redo included, so views rebuild their caches when it moves. An edit costs what the
// octree's insert or remove costs (O(N): a few ms per 1e5 shapes); a droplet cloud, and its undo and
// redo, rebuild the octree once.
class SceneDocument {
public:
    // Undo steps kept; the oldest is forgotten beyond this.
    static constexpr std::size_t kMaxUndoSteps = 200;

    explicit SceneDocument(Scene scene);

    // The shapes.
    const Octree& octree() const { return octree_; }
    std::size_t shapeCount() const { return octree_.shapeCount(); }
    std::size_t slotCount() const { return octree_.slotCount(); }
    const Shape* shape(ShapeId id) const { return octree_.shape(id); }  // null for an empty slot
    const std::string& nameOf(ShapeId id) const;                        // empty when unnamed or empty
    std::optional<ShapeId> findShape(const std::string& name) const;
    // `sphere "d1"` when named, else `sphere 3`: how labels and messages name a shape.
    std::string shapeTitle(ShapeId id) const;

    // The rest of the scene.
    const std::vector<Medium>& media() const { return rest_.media; }
    MediumId ambient() const { return rest_.ambient; }
    const std::vector<Source>& sources() const { return rest_.sources; }
    const std::vector<Detector>& detectors() const { return rest_.detectors; }
    const std::string& unit() const { return rest_.unit; }
    double unitInMetres() const { return rest_.unitInMetres; }
    double wavelengthNm() const { return rest_.wavelengthNm; }
    double wavelengthInSceneUnits() const { return rest_.wavelengthInSceneUnits(); }
    // The camera the scene file starts with. Not an edit: no undo step, no new revision (the GUI sets
    // it from its camera before saving).
    const std::optional<SceneView>& view() const { return rest_.view; }
    void setView(std::optional<SceneView> view) { rest_.view = std::move(view); }
    // The file the scene came from or was last saved to.
    const std::string& origin() const { return rest_.origin; }

    std::uint64_t revision() const { return revision_; }
    // Increases with revision() on every change but an edit of the sources (and its undo and redo): what an
    // OpticalScene is built from (shapes, media, ambient, detectors) is the same while it stays.
    std::uint64_t revisionBesidesSources() const { return revisionBesidesSources_; }

    // Shape edits; each throws EditRefused and changes nothing when the edit is not allowed.
    // A new shape, named (unique among the shapes) or unnamed; returns its id.
    ShapeId addShape(const ShapeSpec& spec, const std::string& name = {});
    void removeShape(ShapeId id);
    // Replaces a shape's geometry and medium (the name stays); the shape itself is ignored by the overlap
    // check. With mergeWithPrevious, when the last undo step is a modifyShape of the same id and nothing
    // is to be redone, this folds into it: a whole drag is one undo step.
    void modifyShape(ShapeId id, const ShapeSpec& spec, bool mergeWithPrevious = false);
    // A new name (unique), or none when empty.
    void renameShape(ShapeId id, const std::string& name);
    // Droplets as the scene file's droplet_cloud generator makes them (drawDropletRadii, placeDroplets),
    // around the current shapes (they may lie inside a box or a sphere, never partly overlap anything),
    // all of `medium`, unnamed. One undo step; returns the new ids in placement order. A cloud that does
    // not fit is refused whole.
    std::vector<ShapeId> generateCloud(const DropletCloudSpec& spec, MediumId medium);

    // Media, ambient and sources. A medium needs a unique non-empty name, n finite and > 0, at most one of
    // kappa and sigma, finite and >= 0; its absorptionPerUnit is recomputed as the loader does.
    MediumId addMedium(const Medium& medium);
    void setMedium(MediumId id, const Medium& medium);
    void setAmbient(MediumId id);
    // With mergeWithPrevious, when the last undo step is a sources edit and nothing is to be redone, this
    // folds into it: dragging a source's handle is one undo step.
    void setSources(std::vector<Source> sources, bool mergeWithPrevious = false);

    // Detectors: each must pass checkDetector (the loader's rules), their names unique; a refusal names the
    // detector and what is wrong ("detector \"screen\": size must be two numbers > 0"). The list in scene
    // order, as setSources; with mergeWithPrevious, folds into the last step when that is a detectors edit and
    // nothing is to be redone (dragging a detector's handle is one undo step).
    void setDetectors(std::vector<Detector> detectors, bool mergeWithPrevious = false);
    // The same edits on one detector, with labels that name it: "add detector \"screen\"", ...
    void addDetector(const Detector& detector);
    void removeDetector(std::size_t index);
    void setDetector(std::size_t index, const Detector& detector, bool mergeWithPrevious = false);

    // nullopt when the shape `spec` describes could be added (or, with `ignore`, replace that shape),
    // else the message the edit would be refused with.
    std::optional<std::string> checkPlacement(const ShapeSpec& spec, std::optional<ShapeId> ignore = {}) const;

    // History. undo and redo do nothing when there is nothing to undo or redo. A new edit clears redo.
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    void undo();
    void redo();
    // "add sphere", "move sphere \"d1\"", "generate 500 droplets"...; empty when there is none.
    std::string undoLabel() const { return undo_.empty() ? std::string() : undo_.back().label; }
    std::string redoLabel() const { return redo_.empty() ? std::string() : redo_.back().label; }
    std::size_t undoDepth() const { return undo_.size(); }
    std::size_t redoDepth() const { return redo_.size(); }

    // The scene as it is now, compacted: the live shapes cloned in slot order (no null entries), names
    // parallel, every shape explicit. For tracing (OpticalScene) and saving (writeScene). When
    // slotOfShape is given, (*slotOfShape)[i] is the slot of the compact scene's shape i.
    Scene toScene(std::vector<ShapeId>* slotOfShape = nullptr) const;

private:
    // What an undo step changes. A shape slot goes from `before` to `after` (null: empty), names with it.
    struct SlotChange {
        ShapeId id;
        std::unique_ptr<Shape> before;
        std::unique_ptr<Shape> after;
        std::string nameBefore;
        std::string nameAfter;
    };
    struct Rename {
        ShapeId id;
        std::string before;
        std::string after;
    };
    struct Properties {
        std::vector<Medium> media;
        MediumId ambient;
        std::vector<Source> sources;
        std::vector<Detector> detectors;
    };
    enum class StepKind { Modify, Sources, Detectors, Other };
    struct Step {
        std::string label;
        StepKind kind = StepKind::Other;
        std::vector<SlotChange> shapes;
        std::vector<Rename> renames;
        std::optional<Properties> before;  // set, with `after`, by media, ambient and source edits
        std::optional<Properties> after;
    };

    // Applies a new step, records it (dropping the oldest beyond kMaxUndoSteps) and clears redo.
    void commit(Step step);
    // The revisions after a change of `kind`.
    void advance(StepKind kind);
    void apply(const Step& step, bool forward);
    void applyShapeChanges(const std::vector<SlotChange>& changes, bool forward);
    void setSlot(ShapeId id, std::unique_ptr<Shape> shape, const std::string& name);
    void setName(ShapeId id, const std::string& name);
    void setProperties(const Properties& properties);
    Properties properties() const { return {rest_.media, rest_.ambient, rest_.sources, rest_.detectors}; }
    void commitProperties(std::string label, Properties after, StepKind kind = StepKind::Other);
    // Commits a detectors edit labelled `label`, or folds it into the last one (setDetectors).
    void commitDetectors(std::string label, std::vector<Detector> detectors, bool mergeWithPrevious);
    const Detector& liveDetector(std::size_t index) const;

    // Checks shared by the edits; each throws EditRefused.
    const Shape& liveShape(ShapeId id) const;
    std::unique_ptr<Shape> shapeFor(const ShapeSpec& spec) const;
    void checkName(const std::string& name, std::optional<ShapeId> owner) const;
    void checkMediumId(MediumId id) const;
    // Refuses media whose models fail at a wavelength the sources emit (findWavelengthCoverageProblem).
    void checkWavelengths(const Properties& properties) const;
    Medium checkedMedium(const Medium& medium, std::optional<MediumId> replacing) const;
    std::optional<std::string> overlapOf(const Shape& shape, std::optional<ShapeId> ignore) const;
    // Refuses a scene whose reach over its smallest feature breaks kMaxScaleRatio (docs/limits.md): the live
    // shapes with what an edit adds (`added`, named `what` in the message) in place of `replacing`, and the
    // sources and detectors of `properties`.
    void checkScale(const ScaleExtremes& added, const std::string& what, std::optional<ShapeId> replacing,
                    const Properties& properties) const;
    void checkScale(const Shape& shape, std::optional<ShapeId> replacing) const;
    std::string modifyLabel(ShapeId id, const Shape& before, const Shape& after) const;

    Octree octree_;
    std::vector<std::string> names_;  // by slot
    std::unordered_map<std::string, ShapeId> nameIndex_;
    Scene rest_;  // the scene without its shapes, which octree_ and names_ hold
    std::uint64_t revision_ = 0;
    std::uint64_t revisionBesidesSources_ = 0;
    // The extremes of every shape, source and detector this document has held: when a new one keeps them
    // within the limit, the scene surely is, and checkScale need not visit every shape.
    ScaleExtremes seen_;
    std::deque<Step> undo_;
    std::vector<Step> redo_;
};

}  // namespace dropscope
