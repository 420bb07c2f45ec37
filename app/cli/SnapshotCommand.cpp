#include "cli/SnapshotCommand.hpp"

#include "cli/AtomicFile.hpp"
#include "cli/BadInput.hpp"
#include "cli/Cli.hpp"
#include "render/RenderError.hpp"
#include "scene/SceneLoader.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <ostream>
#include <sstream>

namespace dropscope {

namespace {

constexpr int kMaxPixels = 8192;
constexpr std::uint64_t kMaxDrawnPaths = 100000;

// "x,y,z": three finite numbers.
Point parsePoint(const std::string& option, const std::string& text) {
    std::istringstream in(text);
    Point p;
    char comma1 = 0;
    char comma2 = 0;
    if (!(in >> p.x() >> comma1 >> p.y() >> comma2 >> p.z()) || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
        !p.allFinite()) {
        throw BadInputError(option + ": expected three numbers x,y,z, got \"" + text + "\"");
    }
    return p;
}

}  // namespace

CLI::App* addSnapshotCommand(CLI::App& app, SnapshotCommandOptions& options) {
    CLI::App* command = app.add_subcommand("snapshot", "Render the scene headless (OSMesa) into a PNG");
    command->add_option("scene", options.scenePath, "Scene file (docs/scene-format.md)")->required();
    command->add_option("--out", options.outPath, "PNG file to write")->required();
    command->add_option("--width", options.render.width, "Image width in pixels")
        ->capture_default_str()
        ->check(CLI::Range(16, kMaxPixels));
    command->add_option("--height", options.render.height, "Image height in pixels")
        ->capture_default_str()
        ->check(CLI::Range(16, kMaxPixels));
    command->add_option("--eye", options.eye, "Camera position x,y,z (default: the scene's view, else fitted)");
    command->add_option("--target", options.target, "Point looked at x,y,z (default: the view's, else the centre)");
    command->add_option("--fov-deg", options.fovDeg, "Vertical field of view in degrees")->check(CLI::Range(1.0, 179.0));
    command->add_option("--octree-level", options.octreeLevel, "Draw the octree's cells at this level")
        ->check(CLI::Range(0, 30));
    command->add_option("--paths", options.render.paths, "Draw the paths of the first K traced photons")
        ->capture_default_str()
        ->check(CLI::Range(std::uint64_t{0}, kMaxDrawnPaths));
    command->add_option("--photons", options.render.photons, "Photons to trace (default and minimum: K)");
    command->add_option("--seed", options.render.seed, "Seed of the traced photons")->capture_default_str();
    return command;
}

int runSnapshotCommand(SnapshotCommandOptions options, std::ostream& out, std::ostream&) {
    if (!options.eye.empty()) options.render.eye = parsePoint("--eye", options.eye);
    if (!options.target.empty()) options.render.target = parsePoint("--target", options.target);
    if (options.fovDeg > 0.0) options.render.fovDeg = options.fovDeg;
    if (options.octreeLevel >= 0) options.render.octreeLevel = options.octreeLevel;
    if (options.render.eye && options.render.target && (*options.render.eye - *options.render.target).norm() == 0.0) {
        throw BadInputError("--eye and --target must differ");
    }
    const Scene scene = loadScene(options.scenePath);
    if (options.render.paths > 0 && scene.sources.empty()) {
        throw SceneError(scene.origin, "sources", "--paths needs a light source, and the scene has none");
    }
    snapshot::Image image;
    try {
        image = snapshot::renderSnapshot(scene, options.render);
    } catch (const render::RenderError& error) {
        throw std::runtime_error(std::string("rendering failed: ") + error.what());
    }
    const std::string png = snapshot::encodePng(image);
    writeFileAtomically(options.outPath, [&](std::ostream& file) { file << png; });
    out << "snapshot: " << image.width << "x" << image.height << " written to " << options.outPath << '\n';
    return kExitSuccess;
}

}  // namespace dropscope
