#pragma once

#include "render/DrawData.hpp"
#include "transport/Emission.hpp"
#include "tree/Octree.hpp"

namespace dropscope::render {

// Which octree cells to draw.
struct OctreeFilter {
    enum class Mode { All, OnlyLevel, UpToLevel, LeavesOnly };
    Mode mode = Mode::All;
    int level = 0;                 // for OnlyLevel and UpToLevel
    bool occupancyColour = false;  // colour by shapes stored (heat) instead of by level

    bool operator==(const OctreeFilter&) const = default;
};

// Wire boxes of the octree's cells: by level (levelColour), or with `occupancyColour` along viridis by
// the shapes a cell stores over the leaf capacity (maxShapesPerLeaf; a full or overfull cell is yellow).
void addOctreeCells(LineBatch& lines, const Octree& octree, const OctreeFilter& filter);

// One ray's traversal of the octree (Octree::firstHit with a record), for the debugger.
struct RayTraversal {
    Ray ray;
    TraversalRecord record;
};
RayTraversal traceTraversal(const Octree& octree, const Ray& ray);

inline constexpr Colour kTraversalColour{0.0f, 1.0f, 0.85f, 1.0f};  // cyan: unlike every level colour

// The cells the traversal visited, as wire boxes, and the ray up to its hit (or to where it left the
// last cell visited), all in kTraversalColour.
void addTraversal(LineBatch& lines, const RayTraversal& traversal);

}  // namespace dropscope::render
