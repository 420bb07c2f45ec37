#include "cli/SnapshotCommand.hpp"

#include "cli/BadInput.hpp"
#include "cli/Cli.hpp"
#include "cli/WholeNumberOption.hpp"
#include "render/RenderError.hpp"
#include "results/AtomicFile.hpp"
#include "scene/SceneLoader.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <ostream>
#include <sstream>
#include <utility>

namespace dropscope {

namespace {

// "x,y,z": three finite numbers.
Point parsePoint(const std::string& option, const std::string& text) {
    std::istringstream in(text);
    Point p;
    char comma1 = 0;
    char comma2 = 0;
    if (!(in >> p.x() >> comma1 >> p.y() >> comma2 >> p.z()) || comma1 != ',' || comma2 != ',' ||
        !(in >> std::ws).eof() || !p.allFinite()) {
        throw BadInputError(option + ": expected three numbers x,y,z, got \"" + text + "\"");
    }
    return p;
}

// The layer switches beyond the options (docs/rendering.md).
void addLayerOptions(CLI::App& command, SnapshotCommandOptions& options) {
    render::LayerOptions& layers = options.render.layers;
    command
        .add_option("--octree-filter", options.octreeFilter,
                    "Octree cells drawn: only level L, levels <= L (both with --octree-level), or the leaves")
        ->capture_default_str()
        ->check(CLI::IsMember({"level", "upto", "leaves"}));
    command
        .add_option("--octree-colour", options.octreeColour, "Octree cells coloured by level or by occupancy (heat)")
        ->capture_default_str()
        ->check(CLI::IsMember({"level", "occupancy"}));
    command
        .add_option("--colour-by", options.colourBy,
                    "Paths coloured by weight (viridis), by event type, by degree of linear polarisation (viridis) "
                    "or by the colour of their wavelength (CIE 1931)")
        ->capture_default_str()
        ->check(CLI::IsMember({"weight", "event", "dolp", "wavelength"}));
    command
        .add_option("--polarisation", options.polarisation,
                    "Paths and ray tree traced with Stokes vectors, or with the unpolarised reflectance (as trace)")
        ->capture_default_str()
        ->check(CLI::IsMember({"stokes", "none"}));
    command.add_flag("--markers", layers.markers, "Mark the events of the paths and the ray tree");
    command.add_flag("--ray-tree", layers.rayTree, "Draw the ray tree of the first source's central ray");
    command.add_flag("--traversal", layers.traversal, "Draw the octree cells the first source's central ray visits");
    command.add_flag("--sources", layers.sources, "Draw the sources as glyphs");
    command.add_flag("--detectors", layers.detectors,
                     "Draw the detectors: planes (with their images when photons are traced) and far-field cameras");
    command.add_flag("--axes", layers.axes, "Draw the coordinate axes");
    command.add_flag("--grid", layers.grid, "Draw a ground grid under the scene");
    command.add_flag("--no-shapes", options.noShapes, "Leave the shapes out");
    command.add_flag("--translucent", layers.render.translucent, "Draw every shape translucent");
    command.add_option("--select", options.select, "Highlight the shape with this id")
        ->check(CLI::Range(std::int64_t{0}, std::int64_t{RayHit::kNone} - 1));
}

// The layer switches whose meaning depends on other options, checked once all are parsed.
void applyLayerOptions(SnapshotCommandOptions& options) {
    render::LayerOptions& layers = options.render.layers;
    const bool leaves = options.octreeFilter == "leaves";
    if (leaves && options.octreeLevel >= 0) {
        throw BadInputError("--octree-filter leaves: takes no --octree-level (the leaves are at every level)");
    }
    if (!leaves && options.octreeFilter != "level" && options.octreeLevel < 0) {
        throw BadInputError("--octree-filter " + options.octreeFilter + ": needs --octree-level L");
    }
    if (options.octreeColour != "level" && !leaves && options.octreeLevel < 0) {
        throw BadInputError("--octree-colour " + options.octreeColour +
                            ": needs --octree-level L or --octree-filter leaves");
    }
    using Mode = render::OctreeFilter::Mode;
    layers.octree = leaves;  // --octree-level switches it on too (SnapshotOptions::octreeLevel)
    layers.octreeFilter.mode = leaves                           ? Mode::LeavesOnly
                               : options.octreeFilter == "upto" ? Mode::UpToLevel
                                                                : Mode::OnlyLevel;
    layers.octreeFilter.occupancyColour = options.octreeColour == "occupancy";
    if (options.colourBy == "dolp" && options.polarisation == "none") {
        throw BadInputError(
            "--colour-by dolp: needs --polarisation stokes (paths without polarisation have no degree "
            "of polarisation)");
    }
    layers.pathColouring = options.colourBy == "event"        ? render::PathColouring::Event
                           : options.colourBy == "dolp"       ? render::PathColouring::Dolp
                           : options.colourBy == "wavelength" ? render::PathColouring::Wavelength
                                                              : render::PathColouring::Weight;
    options.render.polarisation = options.polarisation == "none" ? PolarisationModel::None : PolarisationModel::Stokes;
    layers.render.shapes = !options.noShapes;
}

// What the scene must have for the switches given.
void checkAgainstScene(const SnapshotCommandOptions& options, const Scene& scene) {
    const snapshot::SnapshotOptions& render = options.render;
    const auto needSources = [&](const char* option) {
        if (scene.sources.empty()) {
            throw SceneError(scene.origin, "sources",
                             std::string(option) + " needs a light source, and the scene has none");
        }
    };
    if (render.paths > 0) needSources("--paths");
    if (render.layers.rayTree) needSources("--ray-tree");
    if (render.layers.traversal) needSources("--traversal");
    if (render.layers.detectors) {
        if (scene.detectors.empty()) {
            throw SceneError(scene.origin, "detectors", "--detectors: the scene has no detectors to draw");
        }
        if (render.photons > 0) needSources("--detectors with --photons");
    }
    if (options.select >= 0 && static_cast<std::uint64_t>(options.select) >= scene.shapes.size()) {
        throw SceneError(scene.origin, "shapes",
                         "--select " + std::to_string(options.select) + ": no such shape (the scene has " +
                             std::to_string(scene.shapes.size()) + ", ids from 0)");
    }
}

}  // namespace

CLI::App* addSnapshotCommand(CLI::App& app, SnapshotCommandOptions& options) {
    CLI::App* command = app.add_subcommand("snapshot", "Render the scene headless (OSMesa) into a PNG");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_option("--out", options.outPath, "PNG file to write")->required();
    command->add_option("--width", options.render.width, "Image width in pixels")
        ->capture_default_str()
        ->check(CLI::Range(kMinSnapshotPixels, kMaxSnapshotPixels));
    command->add_option("--height", options.render.height, "Image height in pixels")
        ->capture_default_str()
        ->check(CLI::Range(kMinSnapshotPixels, kMaxSnapshotPixels));
    command->add_option("--eye", options.eye, "Camera position x,y,z (default: the scene's view, else fitted)");
    command->add_option("--target", options.target, "Point looked at x,y,z (default: the view's, else the centre)");
    command->add_option("--fov-deg", options.fovDeg, "Vertical field of view in degrees")
        ->check(CLI::Range(1.0, 179.0));
    command->add_option("--octree-level", options.octreeLevel, "Draw the octree's cells at this level")
        ->check(CLI::Range(0, 30));
    command->add_option("--paths", options.render.paths, "Draw the paths of the first K traced photons")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kMaxDrawnPaths));
    command->add_option("--photons", options.render.photons, "Photons to trace (default and minimum: K)")
        ->transform(wholeNumberIn(0, kMaxSnapshotPhotons));
    command->add_option("--seed", options.render.seed, "Seed of the traced photons")
        ->capture_default_str()
        ->transform(wholeNumberIn(0, kNoUpperBound));
    addLayerOptions(*command, options);
    return command;
}

namespace {

// The options with every check that needs no scene done: the camera and the layers resolved.
SnapshotCommandOptions resolvedOptions(SnapshotCommandOptions options) {
    if (options.eye) options.render.eye = parsePoint("--eye", *options.eye);
    if (options.target) options.render.target = parsePoint("--target", *options.target);
    if (options.fovDeg > 0.0) options.render.fovDeg = options.fovDeg;
    if (options.octreeLevel >= 0) options.render.octreeLevel = options.octreeLevel;
    if (options.render.eye && options.render.target && (*options.render.eye - *options.render.target).norm() == 0.0) {
        throw BadInputError("--eye and --target must differ");
    }
    applyLayerOptions(options);
    return options;
}

}  // namespace

snapshot::Image renderSnapshotImage(SnapshotCommandOptions given, const Scene& scene) {
    SnapshotCommandOptions options = resolvedOptions(std::move(given));
    checkAgainstScene(options, scene);
    if (options.select >= 0) options.render.layers.selected = static_cast<ShapeId>(options.select);
    try {
        return snapshot::renderSnapshot(scene, options.render);
    } catch (const std::invalid_argument& error) {
        throw BadInputError(error.what());
    } catch (const render::RenderError& error) {
        throw std::runtime_error(std::string("rendering failed: ") + error.what());
    }
}

int runSnapshotCommand(SnapshotCommandOptions options, std::ostream& out, std::ostream&) {
    resolvedOptions(options);  // bad options are refused before the scene is read
    const Scene scene = loadScene(options.scenePath);
    const snapshot::Image image = renderSnapshotImage(options, scene);
    const std::string png = snapshot::encodePng(image);
    try {
        writeFileAtomically(options.outPath, [&](std::ostream& file) { file << png; });
    } catch (const std::runtime_error& error) {
        throw BadInputError(error.what());  // an unusable output path, like query's and trace's
    }
    out << "snapshot: " << image.width << "x" << image.height << " written to " << options.outPath << '\n';
    return kExitSuccess;
}

}  // namespace dropscope
