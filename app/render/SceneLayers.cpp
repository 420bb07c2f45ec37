#include "render/SceneLayers.hpp"

#include "render/Guides.hpp"
#include "render/PolarisationEllipse.hpp"
#include "render/RayTreeLayer.hpp"
#include "render/SourceGlyphs.hpp"

namespace dropscope::render {

Eigen::AlignedBox3d sceneBounds(const std::vector<std::unique_ptr<Shape>>& shapes) {
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : shapes) {
        if (shape) bounds.extend(shape->bounds());
    }
    if (bounds.isEmpty()) bounds = Eigen::AlignedBox3d(Point::Constant(-1.0), Point::Constant(1.0));
    return bounds;
}

namespace {

// Adds one layer's lines through `add(batch)`: straight into `lines`, or, with a slice plane, cut to its
// kept side on the way.
template <class AddLayer>
void addSliced(LineBatch& lines, const std::optional<SlicePlane>& slice, const Anchor& anchor, AddLayer add) {
    if (!slice) {
        add(lines);
        return;
    }
    LineBatch layer(anchor);
    add(layer);
    appendKeptSegments(lines, layer, *slice, anchor);
}

}  // namespace

SceneLayers buildSceneLayers(const LayerInputs& inputs, const LayerOptions& options, const Anchor& anchor) {
    SceneLayers layers{LineBatch(anchor), {}, TriangleBatch(anchor), LineBatch(anchor)};
    LineBatch& lines = layers.lines;
    const std::optional<SlicePlane>& slice = options.slice;
    const ChordSplit pathSplit{inputs.octree, layers.chords, inputs.pathSlots};
    const ChordSplit rayTreeSplit{inputs.octree, layers.chords, inputs.rayTreeSlots};
    const ChordSplit* pathChords = slice ? nullptr : &pathSplit;
    const ChordSplit* rayTreeChords = slice ? nullptr : &rayTreeSplit;
    const double size = inputs.bounds.diagonal().norm();
    if (const Event* event = inputs.currentEvent; event && event->polarisation) {
        addSliced(lines, slice, anchor, [&](LineBatch& batch) {
            addPolarisationEllipse(batch, event->position, event->direction, *event->polarisation, kEllipseSize * size);
        });
    }
    if (options.traversal && inputs.traversal) {
        addSliced(lines, slice, anchor, [&](LineBatch& batch) { addTraversal(batch, *inputs.traversal); });
    }
    if (options.rayTree && inputs.rayTree) {
        addSliced(lines, slice, anchor, [&](LineBatch& batch) {
            addRayTree(batch, *inputs.rayTree, kEscapeLength * size, rayTreeChords, inputs.rayTreeDrawOrder);
        });
        if (options.markers) addEventMarkers(layers.markers, *inputs.rayTree, kMarkerRadius * size, anchor);
    }
    if (options.paths && inputs.paths) {
        addSliced(lines, slice, anchor, [&](LineBatch& batch) {
            addPhotonPaths(batch, *inputs.paths, kEscapeLength * size, options.pathColouring, pathChords);
        });
        if (options.markers) addEventMarkers(layers.markers, *inputs.paths, kMarkerRadius * size, anchor);
    }
    if (options.sources) addSourceGlyphs(lines, inputs.sources, kSourceGlyph * size);
    if (options.detectors && inputs.detectors) {
        static const std::vector<DetectorImage> none;
        addDetectorGlyphs(lines, layers.surfaces, *inputs.detectors,
                          inputs.detectorImages ? *inputs.detectorImages : none, inputs.bounds, kSourceGlyph * size);
    }
    if (options.axes) {
        // At the world origin when the scene is around it, else at the scene's centre (the anchor).
        const Point origin = inputs.bounds.contains(Point::Zero()) ? Point(Point::Zero()) : anchor.origin;
        addAxes(lines, origin, kAxisLength * size);
    }
    if (options.octree) {
        addSliced(lines, slice, anchor,
                  [&](LineBatch& batch) { addOctreeCells(batch, inputs.octree, options.octreeFilter); });
    }
    if (options.grid) {
        addSliced(lines, slice, anchor, [&](LineBatch& batch) { addGroundGrid(batch, inputs.bounds, inputs.up); });
    }
    if (slice) layers.markers = keptInstances(layers.markers, *slice, anchor);
    return layers;
}

void uploadScene(Renderer& renderer, const std::vector<std::unique_ptr<Shape>>& shapes, const SceneLayers& layers,
                 const LayerOptions& options) {
    uploadShapes(renderer, shapes, options);
    uploadLayers(renderer, layers);
}

void uploadShapes(Renderer& renderer, const std::vector<std::unique_ptr<Shape>>& shapes, const LayerOptions& options) {
    ShapeInstances instances = buildShapeInstances(shapes, renderer.anchor(), options.selected, &renderer.meshCache());
    if (options.slice) instances = keptShapes(instances, shapes, *options.slice);
    renderer.setShapes(instances);
}

void uploadLayers(Renderer& renderer, const SceneLayers& layers) {
    renderer.setLines(layers.lines, layers.chords);
    renderer.setSurfaces(layers.surfaces);
    renderer.setMarkers(layers.markers);
}

}  // namespace dropscope::render
