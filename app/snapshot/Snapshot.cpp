#include "snapshot/Snapshot.hpp"

#include "render/Layers.hpp"
#include "render/Renderer.hpp"
#include "snapshot/OsmesaContext.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/TraceRun.hpp"

#include <algorithm>

namespace dropscope::snapshot {

namespace {

Eigen::AlignedBox3d sceneBounds(const Octree& octree) {
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : octree.shapes()) {
        if (shape) bounds.extend(shape->bounds());
    }
    if (bounds.isEmpty()) bounds = Eigen::AlignedBox3d(Point::Constant(-1.0), Point::Constant(1.0));
    return bounds;
}

render::Camera snapshotCamera(const Scene& scene, const SnapshotOptions& options, const Eigen::AlignedBox3d& bounds) {
    const double aspect = static_cast<double>(options.width) / static_cast<double>(options.height);
    render::Camera camera;
    if (scene.view) camera = render::Camera::fromView(*scene.view);
    if (options.fovDeg) camera.fovDeg = *options.fovDeg;
    if (!scene.view && !options.eye) camera.fitTo(bounds, aspect);
    if (options.target) camera.target = {options.target->x(), options.target->y(), options.target->z()};
    if (options.eye) camera.eye = {options.eye->x(), options.eye->y(), options.eye->z()};
    if (options.eye && !options.target && !scene.view) {
        camera.target = {bounds.center().x(), bounds.center().y(), bounds.center().z()};
    }
    camera.clipTo(bounds);
    return camera;
}

}  // namespace

Image renderSnapshot(const Scene& scene, const SnapshotOptions& options) {
    const OpticalScene optical(scene);
    const Eigen::AlignedBox3d bounds = sceneBounds(optical.octree());
    const render::Anchor anchor{bounds.center()};

    OsmesaContext context(options.width, options.height);
    render::Renderer renderer(context.gl());
    renderer.setAnchor(anchor);
    renderer.setShapes(render::buildShapeInstances(optical.octree().shapes(), anchor));

    render::LineBatch lines(anchor);
    if (options.octreeLevel) {
        render::addOctreeCells(lines, optical.octree(), {render::OctreeFilter::Mode::OnlyLevel, *options.octreeLevel});
    }
    if (options.paths > 0 && !scene.sources.empty()) {
        TraceSettings settings;
        settings.photons = std::max(options.photons, options.paths);
        settings.paths = options.paths;
        settings.seed = options.seed;
        const TraceResult traced = runTrace(optical, scene.sources, settings);
        render::addPhotonPaths(lines, traced.paths, 0.5 * bounds.diagonal().norm());
    }
    renderer.setLines(lines);

    renderer.draw(snapshotCamera(scene, options, bounds), render::RenderOptions{}, options.width, options.height);
    return context.read();
}

}  // namespace dropscope::snapshot
