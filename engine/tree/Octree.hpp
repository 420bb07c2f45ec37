#pragma once

#include "geometry/Box.hpp"
#include "geometry/SphereGeometry.hpp"
#include "tree/LargePageAllocator.hpp"
#include "tree/OctreeTypes.hpp"
#include "tree/SpherePrefilter.hpp"

#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace dropscope {

class BoundingBox;

// The index that finds the next shape a photon meets (seed 000 chapter 2): octants of equal volume
// down to `maxDepth`, leaves of at most `maxShapesPerLeaf` shapes. docs/octree.md has the design.
//
// A shape is stored in every child cell it overlaps, with cells inflated by margin() so that rounding
// can never hide a shape from a ray that grazes a cell boundary; a shape that overlaps all eight
// children of a cell stays in that cell instead (a glass cell around a whole cloud is then tested
// once per ray, not in every leaf). A cell's spheres are also packed by value (SphereLanes: structure of
// arrays, single precision, in cache-line SphereBlocks), for a conservative vectorised prefilter; the few that pass it
// get the exact SphereGeometry::distanceToSurface from the sphere's double centre and radius, kept once per sphere, the
// same code as Sphere itself, so bit-identical. Shapes are placed into growable per-cell lists, which are then frozen
// into flat arrays for the queries; an insert or remove thaws, edits and refreezes (O(N), a few ms per 1e5 shapes).
class Octree {
public:
    explicit Octree(std::vector<std::unique_ptr<Shape>> shapes, OctreeSettings settings = {},
                    OctreeBuild build = OctreeBuild::TopDown);
    ~Octree();
    Octree(Octree&&) noexcept;
    Octree& operator=(Octree&&) noexcept;

    // Ids are positions in the vector the octree was built from, then insertion order. A removed
    // shape leaves an empty slot, so ids never change.
    std::size_t slotCount() const { return shapes_.size(); }
    std::size_t shapeCount() const { return liveShapes_; }
    const Shape* shape(ShapeId id) const { return id < shapes_.size() ? shapes_[id].get() : nullptr; }
    const std::vector<std::unique_ptr<Shape>>& shapes() const { return shapes_; }
    // Whether `id` is a sphere the traversal tests from the octree's own copy of its centre and radius (every
    // Sphere that SphereLanes::packable accepts, which is every one in a real scene).
    bool packsSphere(ShapeId id) const { return id < exactSpheres_.size() && exactSpheres_[id].radius > 0.0; }
    // That sphere's geometry, the same bits as the Sphere's, from the record the traversal has just read when
    // the sphere is its hit (a photon's next crossing reads it there, not from a record of its own). Requires
    // packsSphere(id).
    SphereGeometry packedSphere(ShapeId id) const {
        const ExactSphere& sphere = exactSpheres_[id];
        return SphereGeometry::make(sphere.center, sphere.radius);
    }
    const OctreeSettings& settings() const { return settings_; }
    const CellBounds& rootBounds() const { return rootBounds_; }
    double margin() const { return margin_; }

    // The nearest surface along the ray, exactly as bruteForceFirstHit.
    RayHit firstHit(const Point& p, const Direction& d) const;
    RayHit firstHit(const Point& p, const Direction& d, TraversalRecord& record) const;
    // The stretch [enter, exit] of the ray inside the root cell inflated by margin(), beyond which no
    // stored shape reaches (enter is 0 when p is inside); nullopt when the ray misses it.
    std::optional<std::pair<double, double>> rootSpan(const Point& p, const Direction& d) const;
    // The innermost shape (smallest volume) that encloses p, if any.
    std::optional<ShapeId> locate(const Point& p) const;
    // Calls f(id) for every shape stored in the cells on the path from the root to the leaf holding
    // p: a superset of the shapes whose inflated bounds contain p, so of every shape enclosing p.
    // Nothing when p is outside the root cell.
    template <class F>
    void forEachShapeAlongPath(const Point& p, F&& f) const;
    // The index of the leaf cell holding p, where that path ends: points with one leaf have one path. Nothing
    // when p is outside the root cell. Valid until the next insert, remove or rebuild.
    std::optional<std::uint32_t> leafHolding(const Point& p) const;
    // Calls f(a, b) for every two shapes stored on one path from the root to a leaf (some pairs more than
    // once). A shape is stored on the path to every leaf whose cell, grown by margin(), it reaches (a sphere by
    // its ball, any other shape by Shape::overlaps), which is what firstHit relies on; so every two shapes that
    // reach one such cell are among the pairs.
    template <class F>
    void forEachPairOnAPath(F&& f) const;
    // The same pairs, as f(record(a), record(b)): each shape's record is made once per cell that stores it and
    // kept while the cells below are visited, so f reads what it needs of a shape from the path, not by id.
    template <class Record, class F>
    void forEachPairOnAPath(Record&& record, F&& f) const;
    // Ids of the stored shapes that overlap `shape` (Shape::overlaps), ascending.
    std::vector<ShapeId> overlapping(const Shape& shape) const;

    // Adds a shape in a new slot (id slotCount()), growing the root when it reaches outside.
    ShapeId insert(std::unique_ptr<Shape> shape);
    // Puts a shape back into the empty slot `id` left by remove(), exactly as insert places it (so undoing
    // a removal restores the same id). Throws std::invalid_argument when `shape` is null, id >= slotCount()
    // or the slot is occupied.
    void insertAt(ShapeId id, std::unique_ptr<Shape> shape);
    std::unique_ptr<Shape> remove(ShapeId id);

    // The level whose cells the traversal walks as a uniform grid (0: none): every cell above it is an
    // inner cell (docs/octree.md, "The top grid").
    int gridLevel() const { return gridLevel_; }

    std::vector<LevelStatistics> statistics() const;
    // Calls visit(bounds, level, isLeaf, shapesStored) for every cell, depth first from the root, for
    // drawing; descends into a cell's children only when visit returns true.
    template <class Visit>
    void visitCells(Visit&& visit) const;
    std::size_t bytesUsed() const;

    // The seed's node model: a BoundingBox per cell holding at most 8 children. For tests and the
    // debugger; the flat arrays here stay the source of truth.
    std::unique_ptr<BoundingBox> referenceTree() const;

private:
    static constexpr std::uint32_t kNoChild = 0;  // node 0 is the root, never anyone's child

    // A cell while shapes are being placed (construction, insert, remove).
    struct Node {
        std::uint32_t firstChild = kNoChild;  // the 8 children are consecutive
        std::uint32_t level = 0;
        std::vector<ShapeId> sphereIds;
        std::vector<ShapeId> otherIds;  // boxes, ellipsoids, anything else
        bool isLeaf() const { return firstChild == kNoChild; }
        std::size_t size() const { return sphereIds.size() + otherIds.size(); }
        void add(ShapeId id, bool sphere) { (sphere ? sphereIds : otherIds).push_back(id); }
    };
    // The same cell, frozen for queries: ranges into the flat arrays, so a visit touches 20 bytes of
    // cell and one contiguous run of sphere blocks (a cache line per 4 spheres).
    struct Cell {
        std::uint32_t firstChild;
        std::uint32_t firstBlock;  // into blocks_; its spheres' ids from sphereIds_[4 firstBlock]
        std::uint32_t sphereCount;
        std::uint32_t firstOther;
        std::uint32_t otherCount;
        bool isLeaf() const { return firstChild == kNoChild; }
        std::size_t size() const { return std::size_t{sphereCount} + otherCount; }
    };
    struct Traversal;

    void rebuild(const CellBounds& bounds);
    // What the top-down build reads of each shape, once.
    struct Placing {
        CellBounds extent;
        Point center;  // a sphere's
        double radius;
        const Shape* shape;
        ShapeId id;
        bool sphere;
    };
    // Stores the shapes at `positions` of `placing` (ascending, the order they are kept in) at `node` and below,
    // splitting as place() would.
    void placeTopDown(std::uint32_t node, const CellBounds& bounds, std::vector<std::uint32_t>& positions,
                      const std::vector<Placing>& placing);
    // insert and insertAt: stores `shape` in the empty slot `id` and places it.
    void fillSlot(ShapeId id, std::unique_ptr<Shape> shape);
    // rootSpan given 1 / d (componentwise; the traversal has it already), without rootSpan's checks: d must be
    // a valid direction and p finite.
    std::optional<std::pair<double, double>> rootSpan(const Point& p, const Direction& d,
                                                      const Eigen::Vector3d& inverse) const;
    // The root grown by the margin on every side: what rootSpan clips a ray to.
    CellBounds inflatedRoot() const {
        return CellBounds(rootBounds_.min().array() - margin_, rootBounds_.max().array() + margin_);
    }
    // Whether p lies strictly inside the inflated root. Then rootSpan gives a span from exactly 0 for every
    // valid direction: on each axis d moves along, the two faces' crossings have opposite signs and are never
    // NaN (neither offset is 0).
    bool strictlyInsideRoot(const Point& p) const {
        const CellBounds root = inflatedRoot();
        return (p.array() > root.min().array()).all() && (p.array() < root.max().array()).all();
    }
    void freeze();
    void buildGrid();
    void thaw();
    void place(std::uint32_t node, const CellBounds& bounds, ShapeId id, const CellBounds& extent);
    void store(Node& node, ShapeId id) const;
    void split(std::uint32_t node, const CellBounds& bounds);
    // Whether a cell at `level` placed `shapes` shapes into is split (both builds ask this).
    bool overflows(std::size_t shapes, std::uint32_t level) const;
    // Appends the leaf `node`'s 8 children, one level below it, and makes them its children; the first's index.
    std::uint32_t addChildren(std::uint32_t node);
    bool reaches(const Shape& shape, const CellBounds& extent, const CellBounds& cell) const;
    void unstore(std::uint32_t node, const CellBounds& bounds, ShapeId id);
    CellBounds childBounds(const CellBounds& bounds, int child) const;
    // The centre of a child of the cube of half-side `half` around `centre` (the traversal's halving).
    static Point childCentre(const Point& centre, double half, int child) {
        const double quarter = 0.5 * half;
        return {centre.x() + ((child & 1) != 0 ? quarter : -quarter),
                centre.y() + ((child & 2) != 0 ? quarter : -quarter),
                centre.z() + ((child & 4) != 0 ? quarter : -quarter)};
    }
    // The slot of cell (x, y, z) in a grid table of `side` cells a side: x fastest, then y, then z.
    static std::size_t gridSlot(std::size_t x, std::size_t y, std::size_t z, std::size_t side) {
        return (z * side + y) * side + x;
    }
    // Calls f(id) for every shape a frozen cell holds, spheres first.
    template <class F>
    void forEachShapeIn(const Cell& cell, F&& f) const;
    // Calls f(index) for each cell from the root down to the leaf holding p; nothing when p is outside the root.
    template <class F>
    void forEachCellAlongPath(const Point& p, F&& f) const;
    // Depth first from the root; `visit(index, cell, bounds, level)` returns whether to descend.
    template <class Visit>
    void forEachNode(Visit&& visit) const;

    std::vector<std::unique_ptr<Shape>> shapes_;
    std::size_t liveShapes_ = 0;
    OctreeSettings settings_;
    OctreeBuild build_ = OctreeBuild::TopDown;
    CellBounds rootBounds_;
    double margin_ = 0.0;
    std::vector<Node> building_;  // empty between edits
    // What a ray's search reads, in memory the kernel may back with huge pages (tree/LargePageAllocator.hpp).
    template <class T>
    using SearchArray = std::vector<T, LargePageAllocator<T>>;
    SearchArray<Cell> cells_;
    SearchArray<SphereBlock> blocks_;  // each cell's spheres in prefilterFrame_ as SphereLanes, padded to 4
    SearchArray<ShapeId> sphereIds_;   // 4 per block, RayHit::kNone in padding
    // A packed sphere's double centre and radius, for the exact test of the candidates the prefilter leaves
    // (SphereGeometry::make recomputes its band; freeze packs only the spheres whose band it recomputes).
    struct ExactSphere {
        Point center;
        double radius;
    };
    SearchArray<ExactSphere> exactSpheres_;  // at the packed spheres' ids; radius 0 in the other slots
    std::vector<ShapeId> others_;
    double rootHalf_ = 0.0;          // half the root's side
    double coordinateScale_ = 0.0;   // largest |coordinate| of the inflated root, for the prefilter's slack
    PrefilterFrame prefilterFrame_;  // around the root
    double packedReach_ = 0.0;       // the largest PrefilterFrame::reach of a packed sphere
    bool prefetch_ = false;          // whether the traversal prefetches children (a tree too large for the caches)
    // The group of at most 64 spheres from lane `first` of a cell may let the prefilter read kPrefilterFixedLanes
    // lanes of each array (sphereCandidates' readAhead), past its own, when block firstBlock + first / 4 lies
    // before this one: its furthest read, float first + 3 stride + 31 of the cell, is at most
    // 3 (stride - first) + 31 <= 127 floats past that block's start (stride - first <= 32 for a group that
    // reads ahead), so within the 8 blocks from it. 0 in a tree whose blocks pass a core's L2.
    std::uint32_t readAheadBefore_ = 0;
    int gridLevel_ = 0;
    Point gridLow_ = Point::Zero();  // the root's lowest corner
    double gridCell_ = 0.0;          // a grid cell's side
    double gridCellInverse_ = 0.0;
    std::vector<std::uint32_t> grid_;  // the cells of level gridLevel_, at their gridSlot
    // Levels 1 .. gridLevel_ - 1 in the same order, one after the other, when any of their cells holds a
    // shape; empty otherwise.
    std::vector<std::uint32_t> gridAbove_;
    // The grid's planes, for the walk: rows x, y and z of side + 1 (side = 2^gridLevel_) hold plane i, gridLow_ +
    // gridCell_ x i, at entry i, but for the grid's faces, -inf and +inf (the grid's last cell runs to the root's
    // exit); a fourth row is all +inf, for an axis the ray does not move along.
    std::vector<double> gridPlanes_;
};

template <class F>
void Octree::forEachShapeIn(const Cell& cell, F&& f) const {
    const ShapeId* ids = sphereIds_.data() + std::size_t{cell.firstBlock} * SphereBlock::kWidth;
    for (std::uint32_t k = 0; k < cell.sphereCount; ++k) f(ids[k]);
    for (std::uint32_t k = 0; k < cell.otherCount; ++k) f(others_[cell.firstOther + k]);
}

template <class Visit>
void Octree::visitCells(Visit&& visit) const {
    forEachNode([&](std::uint32_t, const Cell& cell, const CellBounds& bounds, int level) {
        return visit(bounds, level, cell.isLeaf(), cell.size());
    });
}

template <class F>
void Octree::forEachShapeAlongPath(const Point& p, F&& f) const {
    forEachCellAlongPath(p, [&](std::uint32_t index) { forEachShapeIn(cells_[index], f); });
}

template <class F>
void Octree::forEachCellAlongPath(const Point& p, F&& f) const {
    if (!p.allFinite() || !rootBounds_.contains(p)) return;
    std::uint32_t index = 0;
    CellBounds bounds = rootBounds_;
    while (true) {
        const Cell& cell = cells_[index];
        f(index);
        if (cell.isLeaf()) return;
        const Point mid = bounds.center();
        int child = 0;
        for (int axis = 0; axis < 3; ++axis) child |= (p[axis] >= mid[axis] ? 1 : 0) << axis;
        index = cell.firstChild + static_cast<std::uint32_t>(child);
        bounds = childBounds(bounds, child);
    }
}

template <class F>
void Octree::forEachPairOnAPath(F&& f) const {
    forEachPairOnAPath([](ShapeId id) { return id; }, f);
}

template <class Record, class F>
void Octree::forEachPairOnAPath(Record&& record, F&& f) const {
    std::vector<std::invoke_result_t<Record&, ShapeId>> path;  // the shapes of the cells from the root down
    const auto visit = [&](const auto& self, std::uint32_t index) -> void {
        const Cell& cell = cells_[index];
        const std::size_t above = path.size();
        forEachShapeIn(cell, [&](ShapeId id) {
            auto made = record(id);
            for (const auto& other : path) f(made, other);
            path.push_back(std::move(made));
        });
        if (!cell.isLeaf()) {
            for (std::uint32_t child = 0; child < 8; ++child) self(self, cell.firstChild + child);
        }
        path.resize(above);
    };
    if (!cells_.empty()) visit(visit, 0);
}

template <class Visit>
void Octree::forEachNode(Visit&& visit) const {
    struct Pending {
        std::uint32_t node;
        CellBounds bounds;
        int level;
    };
    std::vector<Pending> stack{{0, rootBounds_, 0}};
    while (!stack.empty()) {
        const Pending top = stack.back();
        stack.pop_back();
        const Cell& cell = cells_[top.node];
        if (!visit(top.node, cell, top.bounds, top.level) || cell.isLeaf()) continue;
        for (int child = 7; child >= 0; --child) {
            stack.push_back(
                {cell.firstChild + static_cast<std::uint32_t>(child), childBounds(top.bounds, child), top.level + 1});
        }
    }
}

}  // namespace dropscope
