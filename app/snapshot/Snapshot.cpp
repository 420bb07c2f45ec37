#include "snapshot/Snapshot.hpp"

#include "render/Renderer.hpp"
#include "run/TraceRun.hpp"
#include "snapshot/OsmesaContext.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/RayTree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropscope::snapshot {

namespace {

// The box a camera is fitted to: the shapes, and the detectors' glyphs when they are drawn.
Eigen::AlignedBox3d fitBox(const Scene& scene, const SnapshotOptions& options, const Eigen::AlignedBox3d& bounds) {
    if (!options.layers.detectors) return bounds;
    return render::withDetectorGlyphs(bounds, scene.detectors, bounds, render::kSourceGlyph * bounds.diagonal().norm());
}

render::Camera snapshotCamera(const Scene& scene, const SnapshotOptions& options, const Eigen::AlignedBox3d& bounds) {
    const double aspect = static_cast<double>(options.width) / static_cast<double>(options.height);
    render::Camera camera;
    if (scene.view) camera = render::Camera::fromView(*scene.view);
    if (options.fovDeg) camera.fovDeg = *options.fovDeg;
    if (!scene.view && !options.eye) camera.fitTo(fitBox(scene, options, bounds), aspect);
    if (options.target) camera.target = {options.target->x(), options.target->y(), options.target->z()};
    if (options.eye) camera.eye = {options.eye->x(), options.eye->y(), options.eye->z()};
    if (options.eye && !options.target && !scene.view) {
        camera.target = {bounds.center().x(), bounds.center().y(), bounds.center().z()};
    }
    const glm::dvec3 view = camera.target - camera.eye;
    if (!(glm::length(view) > 0.0) || !std::isfinite(glm::length(view))) {
        throw std::invalid_argument("the camera's eye coincides with its target; give --target (or another --eye)");
    }
    // Looking along `up` leaves lookAt without a sideways axis: take the world axis least aligned instead.
    if (glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) < 1e-6) {
        const glm::dvec3 a = glm::abs(glm::normalize(view));
        camera.up = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                    : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                             : glm::dvec3(0, 0, 1);
    }
    return camera;
}

// The data of the layers that need a trace, computed only when they are drawn.
struct TracedData {
    std::optional<TraceResult> traced;
    std::vector<render::DetectorImage> detectorImages;
    std::optional<RayTree> rayTree;
    std::optional<render::RayTraversal> traversal;
};

TracedData traceData(const Scene& scene, const OpticalScene& optical, const SnapshotOptions& options,
                     const render::LayerOptions& layers) {
    TracedData data;
    if (scene.sources.empty()) return data;
    const bool images = layers.detectors && options.photons > 0 &&
                        std::any_of(scene.detectors.begin(), scene.detectors.end(),
                                    [](const Detector& d) { return d.type == DetectorType::Plane; });
    if ((options.paths > 0 && layers.paths) || images) {
        TraceSettings settings;
        settings.photons = std::max(options.photons, options.paths);
        settings.paths = layers.paths ? options.paths : 0;
        settings.seed = options.seed;
        settings.transport.polarisation = options.polarisation;
        TallySet tallies;  // only the paths are drawn, and the planes' images
        if (images) addDetectorTallies(tallies, scene, options.polarisation);
        data.traced = runTrace(optical, scene.sources, settings, tallies);
        if (images) {
            ResultReport report;
            data.traced->tallies.report(report);
            data.detectorImages = render::planeDetectorImages(report, scene.detectors);
        }
    }
    const Source& first = scene.sources.front();
    const Ray central{first.origin, first.direction};
    if (layers.rayTree) {
        RayTreeSettings settings;
        settings.polarisation = options.polarisation;
        data.rayTree = traceRayTree(optical, central, 1.0, settings, emittedPolarisation(first, first.direction));
    }
    if (layers.traversal) data.traversal = render::traceTraversal(optical.octree(), central);
    return data;
}

}  // namespace

Image renderSnapshot(const Scene& scene, const SnapshotOptions& options) {
    const OpticalScene optical(scene);
    const Eigen::AlignedBox3d bounds = render::sceneBounds(optical.octree().shapes());
    const render::Anchor anchor{bounds.center()};
    render::Camera camera = snapshotCamera(scene, options, bounds);

    render::LayerOptions layers = options.layers;
    if (options.octreeLevel) {
        layers.octree = true;
        layers.octreeFilter.level = *options.octreeLevel;
    }
    const TracedData data = traceData(scene, optical, options, layers);
    render::LayerInputs inputs{optical.octree(), scene.sources, bounds,
                               Eigen::Vector3d(camera.up.x, camera.up.y, camera.up.z)};
    if (data.traced) inputs.paths = &data.traced->paths;
    if (data.rayTree) inputs.rayTree = &*data.rayTree;
    if (data.traversal) inputs.traversal = &*data.traversal;
    inputs.detectors = &scene.detectors;
    inputs.detectorImages = &data.detectorImages;

    // The near and far planes: around the shapes (and the detectors drawn), and the sources when a layer
    // starts at them.
    Eigen::AlignedBox3d clipBox = fitBox(scene, options, bounds);
    if (layers.sources || layers.rayTree || layers.traversal) {
        for (const Source& source : scene.sources) clipBox.extend(source.origin);
    }
    camera.clipTo(clipBox);

    OsmesaContext context(options.width, options.height);
    render::Renderer renderer(context.gl());
    renderer.setAnchor(anchor);
    render::uploadScene(renderer, optical.octree().shapes(), render::buildSceneLayers(inputs, layers, anchor), layers);
    renderer.draw(camera, layers.render, options.width, options.height);
    return context.read();
}

}  // namespace dropscope::snapshot
