#include "gui/TraceActions.hpp"

#include "tally/FateTally.hpp"

#include "transport/Emission.hpp"
#include "transport/OpticalScene.hpp"

#include <algorithm>
#include <iomanip>
#include <optional>
#include <sstream>

namespace dropscope::gui {

namespace {

TracedWith tracedNow(const AppState& state) {
    return {state.scene.document().revision(), state.traces.fire.polarisation, state.traces.fire.wavelengthBins,
            state.traces.fire.diffraction};
}

// The fire settings' bands over the sources' wavelengths; none for one band or light of one wavelength.
std::optional<WavelengthBins> wavelengthBands(const AppState& state) {
    const SceneDocument& document = state.scene.document();
    const auto [lo, hi] = wavelengthRangeNm(document.sources(), document.wavelengthNm());
    if (state.traces.fire.wavelengthBins <= 1 || !(lo < hi)) return std::nullopt;
    return WavelengthBins{state.traces.fire.wavelengthBins, lo, hi};
}

void startTrace(AppState& state, bool automatic) {
    TraceState& traces = state.traces;
    const SceneDocument& document = state.scene.document();
    traces.fired = tracedNow(state);
    if (document.sources().empty()) return state.ui.status.refuse("nothing to fire: add a source first (Fire panel)");
    TraceSettings settings;
    settings.photons = std::max<std::uint64_t>(traces.fire.photons, 1);
    settings.paths = std::min(traces.fire.paths, settings.photons);
    settings.seed = traces.fire.seed;
    settings.transport.polarisation = traces.fire.polarisation;
    settings.transport.diffraction = traces.fire.diffraction ? DiffractionModel::Fraunhofer : DiffractionModel::None;
    std::vector<ShapeId> slots;
    Scene scene = document.toScene(&slots);
    traces.pendingSlots = std::move(slots);
    traces.job.start(std::move(scene), settings, wavelengthBands(state));
    traces.automatic = automatic;
    if (!automatic) state.ui.status.say("tracing " + std::to_string(settings.photons) + " photons ...");
}

// Shows a tree worked out by traceRayTreeRequest, here or on the job.
void showRayTree(AppState& state, RayTreeOutcome outcome, bool automatic) {
    TraceState& traces = state.traces;
    if (outcome.error) return state.ui.status.refuse("ray tree failed: " + *outcome.error);
    traces.rayTreeScene = std::move(outcome.scene);
    traces.rayTree = std::move(*outcome.tree);
    traces.rayTreeDrawOrder = std::move(outcome.drawOrder);
    ++traces.shownId;
    state.view.layers.rayTree = true;
    if (!automatic) {
        state.ui.status.say("ray tree: " + std::to_string(traces.rayTree->nodes.size()) + " events, " +
                            std::to_string(traces.rayTree->absorbed) + " absorbed");
    }
}

void traceRayTree(AppState& state, bool automatic) {
    TraceState& traces = state.traces;
    const SceneDocument& document = state.scene.document();
    traces.rayTreeTraced = tracedNow(state);
    const auto& sources = document.sources();
    if (sources.empty()) return state.ui.status.refuse("nothing to fire: add a source first (Fire panel)");
    const bool background = document.shapeCount() > traces.rayTreeBackgroundShapes;
    if (background && traces.rayTreeJob.running()) {  // asked again once it is done, with the document as it is then
        using Asked = TraceState::RayTreeAsked;
        traces.rayTreeAsked = automatic && traces.rayTreeAsked != Asked::ByUser ? Asked::ByLive : Asked::ByUser;
        if (!automatic) state.ui.status.say("ray tree: waiting for the tree being traced ...");
        return;
    }
    const Source& source = sources[state.scene.selectedSource()];
    state.ui.status.attempt("ray tree failed", [&] {
        RayTreeRequest request;
        request.generation = state.scene.generation();
        request.revision = document.revisionBesidesSources();
        const std::shared_ptr<const RayTreeScene>& kept = traces.rayTreeScene;
        if (kept && kept->isOf(request.generation, request.revision)) {
            request.kept = kept;
        } else {
            request.scene = document.toScene(&request.slotOfShape);
        }
        request.ray = Ray{source.origin, source.direction};
        request.settings.polarisation = traces.fire.polarisation;
        request.polarisation = emittedPolarisation(source, source.direction);
        if (!background) {
            traces.rayTreeJobWanted = false;  // a tree the job still traces is older than this one
            return showRayTree(state, traceRayTreeRequest(std::move(request)), automatic);
        }
        if (!automatic) {
            state.ui.status.say(request.kept ? std::string("tracing the ray tree ...")
                                             : "ray tree: building the optical scene of " +
                                                   std::to_string(document.shapeCount()) + " shapes ...");
        }
        traces.rayTreeJob.start(std::move(request));
        traces.rayTreeJobAutomatic = automatic;
        traces.rayTreeJobWanted = true;
    });
}

}  // namespace

void fireTrace(AppState& state) { startTrace(state, false); }

void cancelTrace(AppState& state) {
    if (!state.traces.job.running()) return;
    state.traces.job.cancel();
    state.ui.status.say("trace cancelled; the photons traced so far are shown");
}

void fireRayTree(AppState& state) { traceRayTree(state, false); }

void updateTraces(AppState& state) {
    TraceState& traces = state.traces;
    if (auto partial = traces.job.takePartial()) {
        traces.partial = std::move(partial);
        ++traces.talliesId;
    }
    if (auto outcome = traces.job.takeResult()) {
        traces.partial.reset();
        ++traces.talliesId;
        if (outcome->error) {
            state.ui.status.refuse("trace failed: " + *outcome->error);
        } else {
            std::ostringstream text;
            text << (outcome->result.partial ? "trace stopped: " : "traced ") << outcome->result.photons
                 << " photons in " << std::fixed << std::setprecision(2) << outcome->result.seconds << " s";
            traces.trace = TraceShown{std::move(*outcome), std::move(traces.pendingSlots), nullptr};
            ++traces.shownId;
            const auto paths = static_cast<int>(traces.trace->outcome.result.paths.size());
            selectEvent(traces, traces.selectedPath < paths ? traces.selectedPath : -1, traces.selectedEvent);
            // A loss is always said, live firing included, as an error: the results lack those photons. The
            // shape is named as the document names it now, through the run's map back to its slots.
            FateTally fates = traces.trace->outcome.result.tallies.get<FateTally>();
            const std::vector<ShapeId>& slots = traces.trace->slotOfShape;
            const SceneDocument& document = state.scene.document();
            fates.nameShapes([&](ShapeId id) {
                return id < slots.size() ? document.shapeTitle(slots[id]) : "shape " + std::to_string(id);
            });
            if (const auto warning = fates.lossWarning()) {
                state.ui.status.refuse(text.str() + "; " + *warning);
            } else if (!traces.automatic) {
                state.ui.status.say(text.str());
            }
        }
    }
    if (auto outcome = traces.rayTreeJob.takeResult(); outcome && traces.rayTreeJobWanted) {
        traces.rayTreeJobWanted = false;
        showRayTree(state, std::move(*outcome), traces.rayTreeJobAutomatic);
    }
    if (const auto asked = traces.rayTreeAsked; asked != TraceState::RayTreeAsked::No && !traces.rayTreeJob.running()) {
        traces.rayTreeAsked = TraceState::RayTreeAsked::No;
        traceRayTree(state, asked == TraceState::RayTreeAsked::ByLive);
    }
    if (!traces.fire.live) return;
    const TracedWith now = tracedNow(state);
    if (traces.trace && !traces.job.running() && traces.fired != now) startTrace(state, true);
    if (traces.rayTree && traces.rayTreeTraced != now) traceRayTree(state, true);
}

void selectEvent(TraceState& traces, int path, int event) {
    traces.traversal.reset();
    if (!traces.trace || path < 0 || path >= static_cast<int>(traces.trace->outcome.result.paths.size())) {
        traces.selectedPath = -1;
        return;
    }
    const auto& events = traces.trace->outcome.result.paths[static_cast<std::size_t>(path)].events;
    traces.selectedPath = path;
    traces.selectedEvent = std::clamp(event, 0, std::max(0, static_cast<int>(events.size()) - 1));
    if (events.empty()) return;
    const Event& from = events[static_cast<std::size_t>(traces.selectedEvent)];
    if (from.type == EventType::Escape || from.type == EventType::Absorb || from.type == EventType::Lost) return;
    // The segment leaving this event, searched in the octree of the traced scene (built once per trace):
    // the cells visited and the shapes tested, as the photon saw them.
    if (!traces.trace->octree) {
        const Scene& scene = traces.trace->outcome.scene;
        std::vector<std::unique_ptr<Shape>> shapes;
        for (const auto& shape : scene.shapes) shapes.push_back(shape->clone());
        traces.trace->octree = std::make_shared<const Octree>(std::move(shapes), scene.octree);
    }
    traces.traversal = render::traceTraversal(*traces.trace->octree, Ray{from.position, from.direction});
}

void stepEvent(TraceState& traces, int delta) {
    if (traces.selectedPath < 0) {
        if (traces.trace && !traces.trace->outcome.result.paths.empty()) selectEvent(traces, 0, 0);
        return;
    }
    selectEvent(traces, traces.selectedPath, traces.selectedEvent + delta);
}

ShownTallies shownTallies(const TraceState& traces) {
    if (traces.partial && traces.job.running()) {
        return {&traces.partial->tallies, traces.partial->photons, traces.partial->requested, true};
    }
    if (!traces.trace) return {};
    const TraceResult& result = traces.trace->outcome.result;
    return {&result.tallies, result.photons, result.requested, false};
}

void forgetTraces(TraceState& traces) {
    if (traces.trace || traces.rayTree) ++traces.shownId;
    ++traces.talliesId;
    traces.partial.reset();
    traces.trace.reset();
    traces.rayTree.reset();
    traces.rayTreeScene.reset();
    traces.rayTreeDrawOrder.reset();
    traces.rayTreeJobWanted = false;  // a tree still being traced was of what is forgotten
    traces.rayTreeAsked = TraceState::RayTreeAsked::No;
    traces.traversal.reset();
    traces.selectedPath = -1;
    traces.selectedEvent = 0;
}

}  // namespace dropscope::gui
