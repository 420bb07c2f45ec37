#pragma once

#include "render/DrawData.hpp"
#include "transport/TraceRun.hpp"
#include "tree/Octree.hpp"

#include <optional>
#include <vector>

namespace dropscope::render {

// Which octree cells to draw.
struct OctreeFilter {
    enum class Mode { All, OnlyLevel, UpToLevel, LeavesOnly };
    Mode mode = Mode::All;
    int level = 0;
    bool occupancyColour = false;  // colour by shapes stored (heat) instead of by level
};

// Wire boxes of the octree's cells.
void addOctreeCells(LineBatch& lines, const Octree& octree, const OctreeFilter& filter);

// Photon paths as polylines, coloured along viridis by the weight of each segment's starting event
// (the analog photon's weight is 1: the top of the map); an escape goes on for `escapeLength`.
void addPhotonPaths(LineBatch& lines, const std::vector<PhotonPath>& paths, double escapeLength);

}  // namespace dropscope::render
