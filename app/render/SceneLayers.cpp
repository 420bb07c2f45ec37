#include "render/SceneLayers.hpp"

#include "render/Guides.hpp"
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

SceneLayers buildSceneLayers(const LayerInputs& inputs, const LayerOptions& options, const Anchor& anchor) {
    SceneLayers layers{LineBatch(anchor), {}};
    LineBatch& lines = layers.lines;
    const double size = inputs.bounds.diagonal().norm();
    if (options.traversal && inputs.traversal) addTraversal(lines, *inputs.traversal);
    if (options.rayTree && inputs.rayTree) {
        addRayTree(lines, *inputs.rayTree, kEscapeLength * size);
        if (options.markers) addEventMarkers(layers.markers, *inputs.rayTree, kMarkerRadius * size, anchor);
    }
    if (options.paths && inputs.paths) {
        addPhotonPaths(lines, *inputs.paths, kEscapeLength * size, options.pathColouring);
        if (options.markers) addEventMarkers(layers.markers, *inputs.paths, kMarkerRadius * size, anchor);
    }
    if (options.sources) addSourceGlyphs(lines, inputs.sources, kSourceGlyph * size);
    if (options.axes) {
        // At the world origin when the scene is around it, else at the scene's centre (the anchor).
        const Point origin = inputs.bounds.contains(Point::Zero()) ? Point(Point::Zero()) : anchor.origin;
        addAxes(lines, origin, kAxisLength * size);
    }
    if (options.octree) addOctreeCells(lines, inputs.octree, options.octreeFilter);
    if (options.grid) addGroundGrid(lines, inputs.bounds, inputs.up);
    return layers;
}

void uploadScene(Renderer& renderer, const std::vector<std::unique_ptr<Shape>>& shapes, const SceneLayers& layers,
                 const LayerOptions& options) {
    renderer.setShapes(buildShapeInstances(shapes, renderer.anchor(), options.selected));
    renderer.setLines(layers.lines);
    renderer.setMarkers(layers.markers);
}

}  // namespace dropscope::render
