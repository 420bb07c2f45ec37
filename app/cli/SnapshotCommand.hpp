#pragma once

#include "scene/Scene.hpp"
#include "snapshot/Image.hpp"
#include "snapshot/Snapshot.hpp"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace dropscope {

struct SnapshotCommandOptions {
    std::string scenePath;
    std::string outPath;
    std::optional<std::string> eye;       // "x,y,z"
    std::optional<std::string> target;    // "x,y,z"
    double fovDeg = 0.0;                  // 0: not given
    int octreeLevel = -1;                 // -1: not given
    std::string octreeFilter = "level";   // level | upto | leaves
    std::string octreeColour = "level";   // level | occupancy
    std::string colourBy = "weight";      // weight | event | dolp (paths)
    std::string polarisation = "stokes";  // stokes | none: of the traced paths and the ray tree
    bool noShapes = false;
    std::int64_t select = -1;  // -1: not given
    snapshot::SnapshotOptions render;
};

// Registers `dropscope snapshot SCENE --out PNG [--width W] [--height H] [--eye x,y,z] [--target x,y,z]
// [--fov-deg F] [--octree-level L] [--paths K] [--photons N] [--seed S]` and the layer switches
// (docs/rendering.md): [--octree-filter level|upto|leaves] [--octree-colour level|occupancy]
// [--colour-by weight|event|dolp] [--polarisation stokes|none] [--markers] [--ray-tree] [--traversal] [--sources]
// [--detectors] [--axes] [--grid]
// [--no-shapes] [--translucent] [--select ID].
CLI::App* addSnapshotCommand(CLI::App& app, SnapshotCommandOptions& options);

// The bounds of snapshot's options, shared with the Python module.
inline constexpr int kMinSnapshotPixels = 16;
inline constexpr int kMaxSnapshotPixels = 8192;
inline constexpr std::uint64_t kMaxDrawnPaths = 100000;
inline constexpr std::uint64_t kMaxSnapshotPhotons = 100'000'000;  // a picture, not a study: seconds, not hours

// The picture runSnapshotCommand writes, of `scene` (options.scenePath and outPath unused): the layer switches
// checked against each other and the scene (BadInputError, SceneError), then rendered headless.
snapshot::Image renderSnapshotImage(SnapshotCommandOptions options, const Scene& scene);

// Renders the scene headless (OSMesa) and writes the PNG whole or not at all.
int runSnapshotCommand(SnapshotCommandOptions options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
