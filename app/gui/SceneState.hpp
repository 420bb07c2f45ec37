#pragma once

#include "edit/SceneDocument.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

namespace dropscope::gui {

// The scene being edited, the file it came from, and what is selected in it. Opening another scene
// replaces the document and clears the selection; generation() tells one document from the next, since
// each one's revisions start again.
class SceneState {
public:
    SceneState(Scene scene, std::filesystem::path file)
        : document_(std::make_unique<SceneDocument>(std::move(scene))), file_(std::move(file)) {}

    SceneDocument& document() { return *document_; }
    const SceneDocument& document() const { return *document_; }
    std::uint64_t generation() const { return generation_; }

    // Where Save writes; empty for the bundled default scene, which is never saved over.
    const std::filesystem::path& file() const { return file_; }
    void setFile(std::filesystem::path file) { file_ = std::move(file); }

    // Another scene in this one's place: nothing selected, the next generation.
    void replace(std::unique_ptr<SceneDocument> document, std::filesystem::path file) {
        document_ = std::move(document);
        file_ = std::move(file);
        ++generation_;
        selectedShape_ = RayHit::kNone;
        selectedSource_ = 0;
        selectedDetector_.reset();
    }

    ShapeId selectedShape() const { return selectedShape_; }
    void selectShape(ShapeId id) { selectedShape_ = id; }
    // The selected source's index among the document's sources, which must not be empty: the selection
    // clamped to the list, which may have shrunk since it was made.
    std::size_t selectedSource() const { return std::min(selectedSource_, document_->sources().size() - 1); }
    void selectSource(std::size_t index) { selectedSource_ = index; }
    // The detector selected in the Detectors panel, if any and still there: while one is, the view shows its
    // handles instead of the source's, and G and A move and aim it.
    std::optional<std::size_t> selectedDetector() const {
        if (!selectedDetector_ || *selectedDetector_ >= document_->detectors().size()) return std::nullopt;
        return selectedDetector_;
    }
    void selectDetector(std::optional<std::size_t> index) { selectedDetector_ = index; }

private:
    std::unique_ptr<SceneDocument> document_;
    std::filesystem::path file_;
    std::uint64_t generation_ = 0;
    ShapeId selectedShape_ = RayHit::kNone;
    std::size_t selectedSource_ = 0;
    std::optional<std::size_t> selectedDetector_;
};

}  // namespace dropscope::gui
