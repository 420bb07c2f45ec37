// What detectors cost: photons per second of the same scenes traced with four detectors (two planes, a far-field
// camera over the whole sky and the absorption per shape) and with none, interleaved in one process, on one
// thread. Both runs count what `dropscope trace` counts (standardTallies, addDetectorTallies: the budget); the
// planes are not absorbing, so both trace the same photons along the same paths. Scenes: a lone water drop
// (few interfaces per photon: the detectors' per-photon work shows most) and a 1e5-droplet cloud (the octree
// search dominates). docs/performance.md ("Detectors").
//
// Run: build/bench/detector_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]
#include "CloudScene.hpp"
#include "PairedRuns.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/StandardTallies.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace dropscope;
using namespace dropscope::bench;

const char* kDrop = R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
  "media": {"air": {"n": 1.000278}, "water": {"n": 1.3337, "kappa": 1.9e-9}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"}],
  "sources": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 1}]})";

// `text` (a scene object) with four detectors: planes of 64 x 64 pixels facing the beam `distance` behind and
// in front of the origin, each `size` wide, a 256 x 256 far-field camera over the whole sky, and the
// absorption per shape.
Scene withDetectors(const std::string& text, double distance, double size) {
    const std::string d = std::to_string(distance), w = std::to_string(size);
    const std::string plane =
        R"("normal": [0, 0, 1], "up": [0, 1, 0], "size": [)" + w + ", " + w + R"(], "pixels": [64, 64]})";
    const std::string detectors = R"(, "detectors": [
      {"type": "plane", "name": "behind", "center": [0, 0, )" +
                                  d + "], " + plane + R"(,
      {"type": "plane", "name": "before", "center": [0, 0, -)" +
                                  d + "], " + plane + R"(,
      {"type": "far_field", "name": "sky", "look": [0, 0, -1], "up": [0, 1, 0], "projection": "equal_area",
       "fov_deg": 360, "pixels": [256, 256]},
      {"type": "shape_absorption", "name": "absorbed"}]})";
    const std::size_t end = text.rfind('}');
    return parseScene(text.substr(0, end) + detectors, "scene");
}

PairedRow measure(const std::string& name, const std::string& text, double distance, double size, std::uint64_t photons,
                  int repeat) {
    const Scene bare = parseScene(text, "scene");
    const Scene detected = withDetectors(text, distance, size);
    const OpticalScene optical(bare);
    const auto run = [&](const Scene& counted) {
        return [&](std::uint64_t count) {
            TraceSettings settings;
            settings.photons = count;
            settings.threads = 1;
            TallySet tallies = standardTallies(180, settings.transport.polarisation);
            addDetectorTallies(tallies, counted, settings.transport.polarisation);
            return runTrace(optical, bare.sources, settings, tallies);
        };
    };
    return measurePair(name, photons, repeat, run(detected), run(bare));
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const PairedOptions options =
            parsePairedOptions(argc, argv, "detector_bench [--photons 2e5] [--cloud-photons 5e4] [--repeat 7]");
        std::vector<PairedRow> rows;
        rows.push_back(measure("lone water drop", kDrop, 3.0, 4.0, options.photons, options.repeat));
        rows.push_back(measure("cloud of 1e5 droplets (bench/CloudScene.hpp)", cloudSceneText(100000, 15.0), 35.0, 60.0,
                               options.cloudPhotons, options.repeat));
        printPairedTable("detector_bench", "4 detectors", "none", options.repeat, rows);
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "detector_bench: " << error.what() << '\n';
        return 2;
    }
}
