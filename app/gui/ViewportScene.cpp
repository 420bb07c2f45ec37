#include "gui/ViewportScene.hpp"

#include "gui/DetectorHandles.hpp"
#include "gui/PathFilter.hpp"
#include "gui/Picking.hpp"
#include "gui/SourceHandles.hpp"
#include "render/Colour.hpp"
#include "tally/DetectorTallies.hpp"

#include <chrono>

namespace dropscope::gui {

namespace {

// The marker of the event the path inspector steps through, as a multiple of the ordinary markers.
constexpr double kCurrentEventMarkerScale = 2.5;

// The event the path inspector is at, if any.
const Event* currentEvent(const TraceState& traces) {
    if (!traces.trace || traces.selectedPath < 0) return nullptr;
    const auto& events = traces.trace->outcome.result.paths[static_cast<std::size_t>(traces.selectedPath)].events;
    return events.empty() ? nullptr : &events[static_cast<std::size_t>(traces.selectedEvent)];
}

// The plane detectors' images in the last trace, when it counted them (their tallies' tables). Only the planes
// report: the view is rebuilt as the camera turns, and a far-field camera's report integrates every pixel's
// solid angle.
std::vector<render::DetectorImage> detectorImages(const TraceState& traces, const std::vector<Detector>& detectors) {
    if (!traces.trace || detectors.empty()) return {};
    ResultReport report;
    for (const PlaneDetectorTally* plane : traces.trace->outcome.result.tallies.all<PlaneDetectorTally>()) {
        plane->report(report);
    }
    return render::planeDetectorImages(report, detectors);
}

}  // namespace

Eigen::AlignedBox3d viewBounds(const AppState& state, const Eigen::AlignedBox3d& shapes) {
    Eigen::AlignedBox3d box = shapes;
    for (const Source& source : state.scene.document().sources()) box.extend(source.origin);
    if (state.view.layers.detectors) {
        box = render::withDetectorGlyphs(box, state.scene.document().detectors(), shapes,
                                         render::kSourceGlyph * shapes.diagonal().norm());
    }
    const double reach = render::kEscapeLength * shapes.diagonal().norm();
    box.extend(box.min() - Eigen::Vector3d::Constant(reach));
    box.extend(box.max() + Eigen::Vector3d::Constant(reach));
    return box;
}

ViewKey viewKey(const AppState& state) {
    const SceneState& scene = state.scene;
    return ViewKey{
        .document = scene.generation(),
        .revision = scene.document().revision(),
        .shapesRevision = scene.document().revisionBesidesSources(),
        .layers = state.view.layers,
        .slice = state.view.slice,
        .selectedShape = scene.selectedShape(),
        .selectedSource = scene.document().sources().empty() ? 0 : scene.selectedSource(),
        .selectedDetector = scene.selectedDetector(),
        .traces = state.traces.shownId,
        .selectedPath = state.traces.selectedPath,
        .selectedEvent = state.traces.selectedEvent,
        .pathFilter = state.traces.pathFilter,
        .up = state.view.camera.up,
    };
}

void ViewportScene::rebuild(const AppState& state, const ViewKey& key) {
    const auto started = std::chrono::steady_clock::now();
    const SceneDocument& document = state.scene.document();
    const TraceState& traces = state.traces;
    const Octree& octree = document.octree();
    const bool shapesKept = shapesStay(key);
    if (!shapesKept) bounds_ = render::sceneBounds(octree.shapes());
    const render::Anchor anchor{bounds_.center()};
    renderer_.setAnchor(anchor);

    render::LayerOptions options = state.view.layers;
    options.selected = state.scene.selectedShape();
    options.slice = slicePlane(state.view.slice);
    const render::RayTraversal* traversal = traces.traversal ? &*traces.traversal : nullptr;
    options.traversal = options.traversal && traversal;
    const glm::dvec3& up = state.view.camera.up;
    render::LayerInputs inputs{octree, document.sources(), bounds_, Eigen::Vector3d(up.x, up.y, up.z)};
    // The paths the Paths panel's filters keep; all of them when it filters nothing.
    std::vector<PhotonPath> kept;
    if (traces.trace) {
        const std::vector<PhotonPath>& paths = traces.trace->outcome.result.paths;
        inputs.paths = &paths;
        inputs.pathSlots = &traces.trace->slotOfShape;
        if (traces.pathFilter != PathFilter{}) {
            for (int index : filterPaths(paths, traces.trace->outcome.scene.detectors, traces.pathFilter))
                kept.push_back(paths[static_cast<std::size_t>(index)]);
            inputs.paths = &kept;
        }
    }
    if (traces.rayTree) {
        inputs.rayTree = &*traces.rayTree;
        if (traces.rayTreeScene) inputs.rayTreeSlots = &traces.rayTreeScene->slotOfShape;
        // Its chords were found among the shapes it was traced through: taken while the document's are those.
        if (traces.rayTreeDrawOrder && traces.rayTreeScene &&
            traces.rayTreeScene->isOf(state.scene.generation(), document.revisionBesidesSources())) {
            inputs.rayTreeDrawOrder = &*traces.rayTreeDrawOrder;
        }
    }
    inputs.traversal = traversal;
    inputs.currentEvent = currentEvent(traces);
    inputs.detectors = &document.detectors();
    const std::vector<render::DetectorImage> images =
        options.detectors ? detectorImages(traces, document.detectors()) : std::vector<render::DetectorImage>{};
    inputs.detectorImages = &images;
    layers_ = render::buildSceneLayers(inputs, options, anchor);

    if (inputs.currentEvent) {
        const double radius = kCurrentEventMarkerScale * render::kMarkerRadius * bounds_.diagonal().norm();
        layers_.markers.push_back(
            render::sphereInstance(inputs.currentEvent->position, radius, anchor, render::kHighlight));
    }
    if (const auto handles = sourceHandles(state, bounds_)) {
        layers_.markers.push_back(
            render::sphereInstance(handles->origin, handles->radius, anchor, kOriginHandleColour));
        if (document.sources()[state.scene.selectedSource()].type != SourceType::PointSource) {
            layers_.markers.push_back(render::sphereInstance(handles->aim, handles->radius, anchor, kAimHandleColour));
        }
    }
    if (const auto handles = detectorHandles(state, bounds_)) {
        if (handles->move) {
            layers_.markers.push_back(
                render::sphereInstance(*handles->move, handles->radius, anchor, kMoveDetectorColour));
        }
        layers_.markers.push_back(render::sphereInstance(handles->aim, handles->radius, anchor, kAimDetectorColour));
    }
    if (!shapesKept) {
        render::uploadShapes(renderer_, octree.shapes(), options);
        ++shapeUploads_;
    }
    render::uploadLayers(renderer_, layers_);
    ++rebuilds_;
    builtFrom_ = key;
    lastRebuildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

bool ViewportScene::shapesStay(const ViewKey& key) const {
    // What uploadShapes reads: the document's shapes and media, the selected shape and the slice plane.
    return builtFrom_ && builtFrom_->document == key.document && builtFrom_->shapesRevision == key.shapesRevision &&
           builtFrom_->selectedShape == key.selectedShape && builtFrom_->slice == key.slice;
}

bool ViewportScene::recolour(const AppState& state, const ViewKey& key) {
    if (!builtFrom_) return false;
    ViewKey selectionMoved = *builtFrom_;
    selectionMoved.selectedShape = key.selectedShape;
    if (selectionMoved != key) return false;
    const SceneDocument& document = state.scene.document();
    for (const ShapeId id : {builtFrom_->selectedShape, key.selectedShape}) {
        if (const Shape* shape = document.shape(id)) {
            renderer_.recolourShape(id, render::shapeColour(*shape, id == key.selectedShape));
        }
    }
    ++rebuilds_;
    ++recolours_;
    builtFrom_ = key;
    return true;
}

bool ViewportScene::draw(AppState& state, int width, int height, const render::Renderer::RasterOverlay& overlay) {
    if (const ViewKey key = viewKey(state); key != builtFrom_ && !recolour(state, key)) rebuild(state, key);
    ViewState& view = state.view;
    const double aspect = static_cast<double>(width) / static_cast<double>(std::max(height, 1));
    if (view.fitRequested) {
        // The shapes, and the detectors when they are drawn (a screen beyond the droplets).
        const Eigen::AlignedBox3d fitted =
            view.layers.detectors ? render::withDetectorGlyphs(bounds_, state.scene.document().detectors(), bounds_,
                                                               render::kSourceGlyph * bounds_.diagonal().norm())
                                  : bounds_;
        view.camera.fitTo(fitted, aspect);
        view.fitRequested = false;
    }
    view.camera.clipTo(viewBounds(state, bounds_));

    const DrawnView drawn{rebuilds_, view.camera, width, height};
    const render::FramebufferBindings target(gl_);
    GLint sampleBuffers = 0;  // a blit into a multisampled framebuffer of another format is an error
    gl_.GetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    const bool keepable = keepImage_ && sampleBuffers == 0 && unkeepableSize_ != std::pair{width, height};
    if (keepable && kept_ == drawn) {
        if (!keptPicture_) {
            image_.copyTo(static_cast<GLuint>(target.draw));
            ++copiedFrames_;
            lastDrawn_ = drawn;
            return false;
        }
        if (renderer_.showHeld(*keptPicture_, width, height, overlay)) {
            ++copiedFrames_;
            lastDrawn_ = drawn;
            return overlay != nullptr;
        }
    }
    // A picture drawn on the processor with an overlay is kept by the renderer, which holds it before the overlay (a
    // copy in memory), so that later frames draw their overlay over it; any other is drawn into image_ and copied out.
    const bool hold = overlay && renderer_.drawsOnProcessor(view.layers.render, width, height);
    const bool keep = keepable && lastDrawn_ == drawn;
    bool keepInImage = false;
    if (keep) {
        kept_.reset();  // the image is drawn over, or dropped
        keptPicture_.reset();
        if (!hold) {
            keepInImage = image_.bindForDrawing(width, height);
            if (!keepInImage) unkeepableSize_ = std::pair{width, height};
        }
    }
    const bool overlaid = renderer_.draw(view.camera, view.layers.render, width, height, overlay, keep && hold);
    ++drawnFrames_;
    if (keepInImage) {
        target.restore(gl_);
        image_.copyTo(static_cast<GLuint>(target.draw));
        kept_ = drawn;
    } else if (keep && hold && renderer_.lastFrameOnProcessor()) {
        kept_ = drawn;
        keptPicture_ = renderer_.heldPicture();
    }
    lastDrawn_ = drawn;
    return overlaid;
}

}  // namespace dropscope::gui
