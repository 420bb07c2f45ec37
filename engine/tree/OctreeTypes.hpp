#pragma once

#include "tree/RayHit.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace dropscope {

// Scene key "octree" (docs/scene-format.md).
struct OctreeSettings {
    int maxDepth = 10;          // the root is level 0
    int maxShapesPerLeaf = 64;  // a leaf with more is split, unless at maxDepth (64: docs/performance.md)
};

using CellBounds = Eigen::AlignedBox3d;

// How an octree over many shapes is built; both give the same cells, each holding the same shapes in the same
// order (only the cells' numbering differs; docs/octree.md, "Building"). OneByOne places the shapes one at a time,
// splitting a leaf when it overflows, as insert() does: the reference the tests and octree_bench hold TopDown to.
enum class OctreeBuild { TopDown, OneByOne };

// One cell a ray passed through, in visiting order, for the debugger.
struct CellVisit {
    std::uint32_t node;
    int level;
    CellBounds bounds;
    double tEnter;
    double tExit;
    bool leaf;
};

// Everything firstHit did for one ray.
struct TraversalRecord {
    std::vector<CellVisit> cells;
    // Shapes whose exact distance was computed (the spheres the prefilter let through, every other shape),
    // in testing order, repeats included.
    std::vector<ShapeId> shapesTested;
    std::size_t distanceEvaluations = 0;
    RayHit hit;
};

struct LevelStatistics {
    int level = 0;
    std::size_t cells = 0;
    std::size_t leaves = 0;
    std::size_t shapesStored = 0;            // references held by cells of this level
    std::vector<std::size_t> shapesPerLeaf;  // histogram: [k] = leaves holding k shapes
    std::size_t bytes = 0;                   // nodes and their shape lists
};

}  // namespace dropscope
