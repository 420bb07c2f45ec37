#include "gui/Actions.hpp"

#include "gui/ShapeDescription.hpp"
#include "gui/TraceActions.hpp"
#include "results/AtomicFile.hpp"
#include "results/PathsJsonl.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneWriter.hpp"

#include <ctime>
#include <iomanip>
#include <sstream>

namespace dropscope::gui {

namespace {

std::string shapeLabel(const SceneDocument& document, ShapeId id) {
    const Shape* shape = document.octree().shape(id);
    std::string text = "shape " + std::to_string(id);
    if (shape) text += " (" + shapeTypeLabel(*shape) + ")";
    return text;
}

}  // namespace

void undo(AppState& state) {
    SceneDocument& document = state.scene.document();
    if (!document.canUndo()) return state.ui.status.refuse("nothing to undo");
    const std::string label = document.undoLabel();
    document.undo();
    state.ui.status.say("undid: " + label);
}

void redo(AppState& state) {
    SceneDocument& document = state.scene.document();
    if (!document.canRedo()) return state.ui.status.refuse("nothing to redo");
    const std::string label = document.redoLabel();
    document.redo();
    state.ui.status.say("redid: " + label);
}

void deleteSelected(AppState& state) {
    SceneDocument& document = state.scene.document();
    const ShapeId selected = state.scene.selectedShape();
    if (selected == RayHit::kNone || !document.octree().shape(selected)) {
        return state.ui.status.refuse("select a shape to delete (click it)");
    }
    const std::string label = shapeLabel(document, selected);
    document.removeShape(selected);
    state.scene.selectShape(RayHit::kNone);
    state.ui.status.say("deleted " + label + " (Ctrl+Z brings it back)");
}

bool placeDroplet(AppState& state, const Point& center) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Sphere;
    spec.center = center;
    spec.radius = state.placement.radius;
    spec.medium = state.placement.medium;
    return state.ui.status.attempt("droplet not placed", [&] {
        const ShapeId id = state.scene.document().addShape(spec);
        state.scene.selectShape(id);
        std::ostringstream text;
        text << "placed droplet " << id << " at ";
        printPoint(text, center) << ", radius " << state.placement.radius;
        state.ui.status.say(text.str());
    });
}

MediumId firstDropletMedium(const SceneDocument& document) {
    for (MediumId m = 0; m < document.media().size(); ++m) {
        if (m != document.ambient()) return m;
    }
    return document.ambient();
}

bool openScene(AppState& state, const std::filesystem::path& file) {
    return state.ui.status.attempt("could not open", [&] {
        auto document = std::make_unique<SceneDocument>(loadScene(file));
        state.traces.job.discard();  // a run of the old scene must not arrive as this one's
        state.scene.replace(std::move(document), file);
        state.ui.panels = {};
        const SceneDocument& opened = state.scene.document();
        state.placement.medium = firstDropletMedium(opened);
        forgetTraces(state.traces);
        state.view.fitRequested = !opened.view();
        if (const auto& view = opened.view()) state.view.camera = render::Camera::fromView(*view);
        state.ui.status.say("opened " + file.string() + ": " + std::to_string(opened.shapeCount()) + " shapes");
    });
}

bool saveScene(AppState& state, const std::filesystem::path& file) {
    if (file.empty()) {
        state.ui.status.refuse("give a file name to save the scene to");
        return false;
    }
    return state.ui.status.attempt("not saved", [&] {
        Scene scene = state.scene.document().toScene();
        scene.view = state.view.camera.toView();
        writeFileAtomically(file, [&](std::ostream& out) { writeScene(scene, out); });
        state.scene.setFile(file);
        state.ui.status.say("saved " + file.string());
    });
}

bool exportPaths(AppState& state, const std::filesystem::path& file) {
    if (!state.traces.trace || state.traces.trace->outcome.result.paths.empty()) {
        state.ui.status.refuse("no recorded paths to export: fire photons first");
        return false;
    }
    return state.ui.status.attempt("paths not exported", [&] {
        const TraceShown& shown = *state.traces.trace;
        writeFileAtomically(file, [&](std::ostream& out) {
            writePathsJsonl(shown.outcome.result.paths, shown.outcome.scene.media, out);
        });
        state.ui.status.say("exported " + std::to_string(shown.outcome.result.paths.size()) + " paths to " +
                            file.string());
    });
}

std::filesystem::path timestampedScreenshotPath(const std::filesystem::path& directory,
                                                std::chrono::system_clock::time_point when) {
    const std::time_t time = std::chrono::system_clock::to_time_t(when);
    std::tm local{};
    localtime_r(&time, &local);
    std::ostringstream stem;
    stem << "dropscope-" << std::put_time(&local, "%Y%m%d-%H%M%S");
    std::filesystem::path path = directory / (stem.str() + ".png");
    for (int k = 2; std::filesystem::exists(path); ++k)
        path = directory / (stem.str() + "-" + std::to_string(k) + ".png");
    return path;
}

}  // namespace dropscope::gui
