#pragma once

#include "snapshot/Snapshot.hpp"

#include <iosfwd>
#include <string>

namespace CLI {
class App;
}

namespace dropscope {

struct SnapshotCommandOptions {
    std::string scenePath;
    std::string outPath;
    std::string eye;     // "x,y,z", empty: not given
    std::string target;  // "x,y,z", empty: not given
    double fovDeg = 0.0;  // 0: not given
    int octreeLevel = -1;  // -1: not given
    snapshot::SnapshotOptions render;
};

// Registers `dropscope snapshot SCENE --out PNG [--width W] [--height H] [--eye x,y,z] [--target x,y,z]
// [--fov-deg F] [--octree-level L] [--paths K] [--photons N] [--seed S]`.
CLI::App* addSnapshotCommand(CLI::App& app, SnapshotCommandOptions& options);

// Renders the scene headless (OSMesa) and writes the PNG whole or not at all.
int runSnapshotCommand(SnapshotCommandOptions options, std::ostream& out, std::ostream& err);

}  // namespace dropscope
