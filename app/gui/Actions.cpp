#include "gui/Actions.hpp"

#include "cli/AtomicFile.hpp"
#include "cli/TraceFiles.hpp"
#include "gui/ShapeDescription.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneWriter.hpp"
#include "transport/OpticalScene.hpp"

#include <algorithm>
#include <ctime>
#include <exception>
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

void forgetTraces(AppState& state) {
    if (state.trace || state.rayTree) ++state.shownTraces;
    state.trace.reset();
    state.rayTree.reset();
    state.traversal.reset();
    state.selectedPath = -1;
    state.selectedEvent = 0;
}

}  // namespace

void undo(AppState& state) {
    if (!state.document->canUndo()) return state.refuse("nothing to undo");
    const std::string label = state.document->undoLabel();
    state.document->undo();
    state.say("undid: " + label);
}

void redo(AppState& state) {
    if (!state.document->canRedo()) return state.refuse("nothing to redo");
    const std::string label = state.document->redoLabel();
    state.document->redo();
    state.say("redid: " + label);
}

void deleteSelected(AppState& state) {
    if (state.selected == RayHit::kNone || !state.document->octree().shape(state.selected)) {
        return state.refuse("select a shape to delete (click it)");
    }
    const std::string label = shapeLabel(*state.document, state.selected);
    state.document->removeShape(state.selected);
    state.selected = RayHit::kNone;
    state.say("deleted " + label + " (Ctrl+Z brings it back)");
}

bool placeDroplet(AppState& state, const Point& centre) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Sphere;
    spec.center = centre;
    spec.radius = state.placementRadius;
    spec.medium = state.placementMedium;
    try {
        const ShapeId id = state.document->addShape(spec);
        state.selected = id;
        std::ostringstream text;
        text << "placed droplet " << id << " at ";
        printPoint(text, centre) << ", radius " << state.placementRadius;
        state.say(text.str());
        return true;
    } catch (const std::exception& error) {
        state.refuse(std::string("droplet not placed: ") + error.what());
        return false;
    }
}

namespace {

void startTrace(AppState& state, bool automatic) {
    state.firedRevision = state.document->revision();
    if (state.document->sources().empty()) return state.refuse("nothing to fire: add a source first (Fire panel)");
    TraceSettings settings;
    settings.photons = std::max<std::uint64_t>(state.fire.photons, 1);
    settings.paths = std::min(state.fire.paths, settings.photons);
    settings.seed = state.fire.seed;
    std::vector<ShapeId> slots;
    Scene scene = state.document->toScene(&slots);
    state.pendingSlots = std::move(slots);
    state.job.start(std::move(scene), settings);
    state.automaticTrace = automatic;
    if (!automatic) state.say("tracing " + std::to_string(settings.photons) + " photons ...");
}

void traceRayTree(AppState& state, bool automatic) {
    state.rayTreeRevision = state.document->revision();
    const auto& sources = state.document->sources();
    if (sources.empty()) return state.refuse("nothing to fire: add a source first (Fire panel)");
    const Source& source = sources[selectedSourceIndex(state, sources)];
    try {
        const OpticalScene optical(state.document->toScene());
        const Ray ray{source.origin, source.direction};
        state.rayTree = traceRayTree(optical, ray, 1.0, RayTreeSettings{});
        ++state.shownTraces;
        state.layers.rayTree = true;
        if (!automatic) {
            state.say("ray tree: " + std::to_string(state.rayTree->nodes.size()) + " events, " +
                      std::to_string(state.rayTree->absorbed) + " absorbed");
        }
    } catch (const std::exception& error) {
        state.refuse(std::string("ray tree failed: ") + error.what());
    }
}

}  // namespace

void fireTrace(AppState& state) { startTrace(state, false); }
void fireTraceAutomatically(AppState& state) { startTrace(state, true); }

void cancelTrace(AppState& state) {
    if (!state.job.running()) return;
    state.job.cancel();
    state.say("trace cancelled; the photons traced so far are shown");
}

void fireRayTree(AppState& state) { traceRayTree(state, false); }

void updateTraces(AppState& state) {
    if (auto outcome = state.job.takeResult()) {
        if (outcome->error) {
            state.refuse("trace failed: " + *outcome->error);
        } else {
            const TraceTally& tally = outcome->result.tally;
            std::ostringstream text;
            text << (outcome->result.partial ? "trace stopped: " : "traced ") << tally.photons << " photons in "
                 << std::fixed << std::setprecision(2) << outcome->result.seconds << " s";
            state.trace = TraceShown{std::move(*outcome), std::move(state.pendingSlots), nullptr};
            ++state.shownTraces;
            const auto paths = static_cast<int>(state.trace->outcome.result.paths.size());
            selectEvent(state, state.selectedPath < paths ? state.selectedPath : -1, state.selectedEvent);
            if (!state.automaticTrace) state.say(text.str());
        }
    }
    const std::uint64_t revision = state.document->revision();
    if (!state.fire.live) return;
    if (state.trace && !state.job.running() && state.firedRevision != revision) fireTraceAutomatically(state);
    if (state.rayTree && state.rayTreeRevision != revision) traceRayTree(state, true);
}

MediumId firstDropletMedium(const SceneDocument& document) {
    for (MediumId m = 0; m < document.media().size(); ++m) {
        if (m != document.ambient()) return m;
    }
    return document.ambient();
}

void selectEvent(AppState& state, int path, int event) {
    state.traversal.reset();
    if (!state.trace || path < 0 || path >= static_cast<int>(state.trace->outcome.result.paths.size())) {
        state.selectedPath = -1;
        return;
    }
    const auto& events = state.trace->outcome.result.paths[static_cast<std::size_t>(path)].events;
    state.selectedPath = path;
    state.selectedEvent = std::clamp(event, 0, std::max(0, static_cast<int>(events.size()) - 1));
    if (events.empty()) return;
    const Event& from = events[static_cast<std::size_t>(state.selectedEvent)];
    if (from.type == EventType::Escape || from.type == EventType::Absorb || from.type == EventType::Lost) return;
    // The segment leaving this event, searched in the octree of the traced scene (built once per trace):
    // the cells visited and the shapes tested, as the photon saw them.
    if (!state.trace->octree) {
        const Scene& scene = state.trace->outcome.scene;
        std::vector<std::unique_ptr<Shape>> shapes;
        for (const auto& shape : scene.shapes) shapes.push_back(shape->clone());
        state.trace->octree = std::make_shared<const Octree>(std::move(shapes), scene.octree);
    }
    state.traversal = render::traceTraversal(*state.trace->octree, Ray{from.position, from.direction});
}

void stepEvent(AppState& state, int delta) {
    if (state.selectedPath < 0) {
        if (state.trace && !state.trace->outcome.result.paths.empty()) selectEvent(state, 0, 0);
        return;
    }
    selectEvent(state, state.selectedPath, state.selectedEvent + delta);
}

bool openScene(AppState& state, const std::filesystem::path& file) {
    try {
        auto document = std::make_unique<SceneDocument>(loadScene(file));
        state.job.discard();  // a run of the old scene must not arrive as this one's
        state.document = std::move(document);
        ++state.opened;
        state.scenePath = file;
        state.selected = RayHit::kNone;
        state.selectedSource = 0;
        state.placementMedium = firstDropletMedium(*state.document);
        forgetTraces(state);
        state.fitRequested = !state.document->view();
        if (const auto& view = state.document->view()) state.camera = render::Camera::fromView(*view);
        state.say("opened " + file.string() + ": " + std::to_string(state.document->shapeCount()) + " shapes");
        return true;
    } catch (const std::exception& error) {
        state.refuse(std::string("could not open: ") + error.what());
        return false;
    }
}

bool saveScene(AppState& state, const std::filesystem::path& file) {
    if (file.empty()) {
        state.refuse("give a file name to save the scene to");
        return false;
    }
    try {
        Scene scene = state.document->toScene();
        scene.view = state.camera.toView();
        writeFileAtomically(file, [&](std::ostream& out) { writeScene(scene, out); });
        state.scenePath = file;
        state.say("saved " + file.string());
        return true;
    } catch (const std::exception& error) {
        state.refuse(std::string("not saved: ") + error.what());
        return false;
    }
}

bool exportPaths(AppState& state, const std::filesystem::path& file) {
    if (!state.trace || state.trace->outcome.result.paths.empty()) {
        state.refuse("no recorded paths to export: fire photons first");
        return false;
    }
    try {
        const TraceShown& shown = *state.trace;
        writeFileAtomically(file, [&](std::ostream& out) {
            writePathsJsonl(shown.outcome.result.paths, shown.outcome.scene.media, out);
        });
        state.say("exported " + std::to_string(shown.outcome.result.paths.size()) + " paths to " + file.string());
        return true;
    } catch (const std::exception& error) {
        state.refuse(std::string("paths not exported: ") + error.what());
        return false;
    }
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
