#pragma once

#include "render/SceneLayers.hpp"
#include "scene/Scene.hpp"
#include "snapshot/Image.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <cstdint>
#include <optional>

namespace dropscope::snapshot {

struct SnapshotOptions {
    int width = 800;
    int height = 600;
    std::optional<Point> eye;        // default: the scene's "view", else a three-quarter view fitted to it
    std::optional<Point> target;     // default: the view's target, else the scene's centre
    std::optional<double> fovDeg;    // default: the view's, else 40
    std::optional<int> octreeLevel;  // draw the octree's cells, filtered at this level
    std::uint64_t paths = 0;         // draw the paths of the first K traced photons
    std::uint64_t photons = 0;       // photons to trace (at least `paths`); with layers.detectors, their images
    std::uint64_t seed = 1;
    PolarisationModel polarisation = PolarisationModel::Stokes;  // of the traced paths and the ray tree
    // What is drawn. `octreeLevel` switches the octree on and sets its filter's level; the traversal
    // and the ray tree are those of the first source's central ray (its origin and direction). With
    // layers.detectors the camera's default fit and its clipping hold the detectors' glyphs, and when photons
    // are traced the plane detectors show their images (the scene's detector tallies, addDetectorTallies).
    render::LayerOptions layers;
};

// Renders the scene headless (OSMesa) into an image: the same pixels for the same arguments. Throws
// std::invalid_argument when the camera has no direction (eye on the target).
Image renderSnapshot(const Scene& scene, const SnapshotOptions& options);

}  // namespace dropscope::snapshot
