#include "gui/ViewportScene.hpp"

#include "gui/Picking.hpp"
#include "gui/SourceHandles.hpp"
#include "render/Colour.hpp"

namespace dropscope::gui {

namespace {

// The marker of the event the path inspector steps through, as a multiple of the ordinary markers.
constexpr double kCurrentEventMarkerScale = 2.5;

}  // namespace

Eigen::AlignedBox3d viewBounds(const AppState& state, const Eigen::AlignedBox3d& shapes) {
    Eigen::AlignedBox3d box = shapes;
    for (const Source& source : state.document->sources()) box.extend(source.origin);
    const double reach = render::kEscapeLength * shapes.diagonal().norm();
    box.extend(box.min() - Eigen::Vector3d::Constant(reach));
    box.extend(box.max() + Eigen::Vector3d::Constant(reach));
    return box;
}

ViewKey viewKey(const AppState& state) {
    const auto& sources = state.document->sources();
    return ViewKey{
        .document = state.opened,
        .revision = state.document->revision(),
        .layers = state.layers,
        .slice = state.slice,
        .selectedShape = state.selected,
        .selectedSource = sources.empty() ? 0 : selectedSourceIndex(state, sources),
        .traces = state.shownTraces,
        .selectedPath = state.selectedPath,
        .selectedEvent = state.selectedEvent,
        .up = state.camera.up,
    };
}

void ViewportScene::rebuild(AppState& state, const ViewKey& key) {
    const SceneDocument& document = *state.document;
    const Octree& octree = document.octree();
    bounds_ = render::sceneBounds(octree.shapes());
    state.sceneBounds = bounds_;
    const render::Anchor anchor{bounds_.center()};
    renderer_.setAnchor(anchor);

    render::LayerOptions options = state.layers;
    options.selected = state.selected;
    options.slice = slicePlane(state.slice);
    const render::RayTraversal* traversal = state.traversal ? &*state.traversal : nullptr;
    options.traversal = options.traversal && traversal;
    render::LayerInputs inputs{octree, document.sources(), bounds_,
                               Eigen::Vector3d(state.camera.up.x, state.camera.up.y, state.camera.up.z)};
    if (state.trace) inputs.paths = &state.trace->outcome.result.paths;
    if (state.rayTree) inputs.rayTree = &*state.rayTree;
    inputs.traversal = traversal;
    layers_ = render::buildSceneLayers(inputs, options, anchor);

    if (state.trace && state.selectedPath >= 0) {
        const auto& events = state.trace->outcome.result.paths[static_cast<std::size_t>(state.selectedPath)].events;
        if (!events.empty()) {
            const double radius = kCurrentEventMarkerScale * render::kMarkerRadius * bounds_.diagonal().norm();
            const Point at = events[static_cast<std::size_t>(state.selectedEvent)].position;
            layers_.markers.push_back(render::sphereInstance(at, radius, anchor, render::kHighlight));
        }
    }
    if (const auto handles = sourceHandles(state)) {
        layers_.markers.push_back(
            render::sphereInstance(handles->origin, handles->radius, anchor, kOriginHandleColour));
        const auto& sources = document.sources();
        if (sources[selectedSourceIndex(state, sources)].type != SourceType::PointSource) {
            layers_.markers.push_back(render::sphereInstance(handles->aim, handles->radius, anchor, kAimHandleColour));
        }
    }
    render::uploadScene(renderer_, octree.shapes(), layers_, options);
    ++rebuilds_;
    builtFrom_ = key;
}

void ViewportScene::draw(AppState& state, int width, int height) {
    if (const ViewKey key = viewKey(state); key != builtFrom_) rebuild(state, key);
    const double aspect = static_cast<double>(width) / static_cast<double>(std::max(height, 1));
    if (state.fitRequested) {
        state.camera.fitTo(bounds_, aspect);
        state.fitRequested = false;
    }
    state.camera.clipTo(viewBounds(state, bounds_));
    renderer_.draw(state.camera, state.layers.render, width, height);
}

}  // namespace dropscope::gui
