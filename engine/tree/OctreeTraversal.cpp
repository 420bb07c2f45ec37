// Front-to-back ray traversal of the octree (docs/octree.md, "First hit").
#include "tree/Octree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dropscope {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

struct Octree::Traversal {
    const Octree& tree;
    const Point& p;
    const Direction& d;
    Eigen::Vector3d inverse;  // 1/d, +-inf on zero components (never multiplied by 0: see crossing())
    TraversalRecord* record;
    RayHit hit;

    // Ray parameter at which it crosses the plane x_axis = value; +inf when parallel to it. 0 when p lies on
    // it, also for a subnormal d[axis], whose inverse is infinite (0 x inf would be NaN).
    double crossing(int axis, double value) const {
        return d[axis] == 0.0 ? kInfinity : value == p[axis] ? 0.0 : (value - p[axis]) * inverse[axis];
    }

    PrefilterRay prefilterRay;

    // The exact distance of one shape, offered to the best hit.
    void testExactly(ShapeId id, double distance) {
        const double before = hit.distance;
        hit.offer(id, distance);
        // The prefilter's limit follows the best distance; set here, where it changes, not in every cell.
        if (hit.distance != before) prefilterRay.setBest(hit.distance);
        if (record) {
            record->shapesTested.push_back(id);
            ++record->distanceEvaluations;
        }
    }

    // A cell's x lanes; its y, z and radius lanes follow, each SphereLanes::strideFor(sphereCount) further on.
    const float* lanesOf(const Cell& cell) const { return tree.blocks_[cell.firstBlock].values; }

    // The cell's spheres through the prefilter, then the exact test on the candidates it lets through;
    // then every other shape exactly. Inline in the walks: a call per cell was measurable at 1e3 droplets,
    // where a ray meets two or three cells of about 21 spheres (docs/performance.md).
    [[gnu::always_inline]] void testShapes(const Cell& cell) {
        if (cell.sphereCount > 0) {
            const PrefilterRay& ray = prefilterRay;
            const float* x = lanesOf(cell);
            const unsigned stride = SphereLanes::strideFor(cell.sphereCount);
            for (std::uint32_t first = 0; first < cell.sphereCount; first += 64) {
                // The block from which the group's reads, with the read-ahead, stay within 8 (readAheadBefore_).
                const std::uint32_t block = cell.firstBlock + first / SphereBlock::kWidth;
                const ShapeId* ids =
                    tree.sphereIds_.data() + std::size_t{cell.firstBlock} * SphereBlock::kWidth + first;
                const unsigned count = std::min<std::uint32_t>(cell.sphereCount - first, 64);
                for (std::uint64_t candidates =
                         sphereCandidates(x + first, stride, count, block < tree.readAheadBefore_, ray);
                     candidates != 0; candidates &= candidates - 1) {
                    const ShapeId id = ids[__builtin_ctzll(candidates)];
                    testExactly(id, tree.packedSphere(id).distanceToSurface(p, d));
                }
            }
        }
        for (std::uint32_t k = 0; k < cell.otherCount; ++k) {
            const ShapeId id = tree.others_[cell.firstOther + k];
            testExactly(id, tree.shapes_[id]->distanceToSurface(p, d));
        }
    }

    // Visits the cell over [tEnter, tExit], then its children in the order the ray meets them,
    // stopping as soon as the best hit lies before the next child's entry.
    // The cell is the cube of half-side `half` around `mid`.
    void visit(std::uint32_t index, const Point& mid, double half, int level, double tEnter, double tExit) {
        const Cell& cell = tree.cells_[index];
        if (record) {
            const CellBounds bounds(mid.array() - half, mid.array() + half);
            record->cells.push_back({index, level, bounds, tEnter, tExit, cell.isLeaf()});
        }
        if (cell.size() > 0) testShapes(cell);
        if (cell.isLeaf()) return;

        double planeCrossing[3];
        int child = 0;
        for (int axis = 0; axis < 3; ++axis) {
            planeCrossing[axis] = crossing(axis, mid[axis]);
            // The half the ray is in at tEnter: the far half along d once it has crossed the mid-plane.
            const bool upper =
                d[axis] == 0.0 ? p[axis] >= mid[axis] : (planeCrossing[axis] <= tEnter) == (d[axis] > 0.0);
            child |= (upper ? 1 : 0) << axis;
        }
        // The (at most 4) children the ray crosses, in order; each mid-plane crossing flips one bit.
        int order[4];
        double from[4];
        double to[4];
        int count = 0;
        for (double t = tEnter;;) {
            double next = tExit;
            for (int axis = 0; axis < 3; ++axis) {
                if (planeCrossing[axis] > t) next = std::min(next, planeCrossing[axis]);
            }
            order[count] = child;
            from[count] = t;
            to[count] = next;
            ++count;
            if (next >= tExit || count == 4) break;
            for (int axis = 0; axis < 3; ++axis) {
                if (planeCrossing[axis] == next) child ^= 1 << axis;
            }
            t = next;
        }
        // In a large tree memory latency, not arithmetic, bounds the traversal (docs/performance.md): ask
        // for the children's first sphere blocks (up to 4 cache lines each) before testing the first child.
        for (int k = 0; k < count && tree.prefetch_; ++k) {
            prefetchCell(tree.cells_[cell.firstChild + static_cast<std::uint32_t>(order[k])]);
        }
        for (int k = 0; k < count; ++k) {
            if (hit.distance < from[k]) return;  // nothing further on can be nearer
            visit(cell.firstChild + static_cast<std::uint32_t>(order[k]), childCentre(mid, half, order[k]), 0.5 * half,
                  level + 1, from[k], to[k]);
        }
    }

    // Asks for a cell's first 16 spheres (the lines where each of the four arrays' first 16 lanes begin and
    // end: all of a cell of up to 16, in 4 cache lines or fewer) and its children's cells.
    void prefetchCell(const Cell& cell) const {
        if (cell.sphereCount > 0) {
            const unsigned stride = SphereLanes::strideFor(cell.sphereCount);
            const unsigned last = std::min(stride, 16u) - 1;
            for (unsigned array = 0; array < 4; ++array) {
                const float* begin = lanesOf(cell) + array * stride;
                __builtin_prefetch(begin);
                __builtin_prefetch(begin + last);
            }
        }
        if (!cell.isLeaf()) __builtin_prefetch(tree.cells_.data() + cell.firstChild);
    }

    // Tests the shapes of the inner cells between the root and the grid that the ray enters together with
    // grid cell `here` (coming from grid cell `previous`, unless `first`), outermost first, as visit()
    // would on entering them.
    void enterAbove(const int* here, const int* previous, int gridLevel, bool first) {
        std::size_t offset = 0;
        for (int level = 1; level < gridLevel; ++level) {
            const int shift = gridLevel - level;
            const std::size_t side = std::size_t{1} << level;
            const bool entered = first || (here[0] >> shift) != (previous[0] >> shift) ||
                                 (here[1] >> shift) != (previous[1] >> shift) ||
                                 (here[2] >> shift) != (previous[2] >> shift);
            if (entered) {
                const std::size_t at = gridSlot(std::size_t(here[0] >> shift), std::size_t(here[1] >> shift),
                                                std::size_t(here[2] >> shift), side);
                const Cell& cell = tree.cells_[tree.gridAbove_[offset + at]];
                if (cell.size() > 0) testShapes(cell);
            }
            offset += side * side * side;
        }
    }

    // The same walk as visit() from the root, without the empty levels above the top grid: the root's
    // own shapes, then the grid's cells the ray crosses over [tEnter, tExit], in order (a 3D DDA: the next
    // cell is across the nearest of the three planes ahead; two or three at once through an edge or
    // corner), each visited as visit() would, stopping once the best hit lies before the next cell.
    void walkGrid(const Eigen::Vector3d& start, double tEnter, double tExit) {
        const Cell& root = tree.cells_[0];
        if (root.size() > 0) testShapes(root);
        const int level = tree.gridLevel_;
        const int side = 1 << level;
        const double half = 0.5 * tree.gridCell_;
        const Point& low = tree.gridLow_;
        int index[3];
        int step[3];
        // Where the ray crosses the plane ahead on each axis; +inf in the grid's last cell that way, which
        // (as the recursive walk's last child) the ray leaves only at tExit, on the inflated root, and on an
        // axis the ray does not move along (d 0 there: its only cell is its last). The step below does not
        // branch on which axis the ray crosses next, which is what a DDA cannot predict.
        double next[3];
        // Per axis, the plane ahead of cell i is ahead[axis][i], its lower or upper face in the grid's table of
        // planes: the grid's faces there are -inf and +inf, whose crossings, the last cell's, are +inf; an axis the
        // ray does not move along reads a row of +inf. A load, not a computation, on the chain from one step to
        // the next (docs/performance.md, "The grid's planes from a table").
        const double* ahead[3];
        double scale[3];  // 1/d; 1 where d is 0, whose planes are all +inf
        const auto planeAhead = [&](int axis) {
            const double offset = ahead[axis][index[axis]] - p[axis];
            // offset 0 crosses at 0 also when d[axis] is subnormal (an infinite inverse; 0 x inf is NaN).
            return offset == 0.0 ? 0.0 : offset * scale[axis];
        };
        const std::size_t row = std::size_t(side) + 1;
        for (int axis = 0; axis < 3; ++axis) {
            // Truncation is the floor here: a negative value is clamped to the first cell either way.
            const double cell = (start[axis] - low[axis]) * tree.gridCellInverse_;
            index[axis] = cell < 0.0 ? 0 : cell >= side ? side - 1 : static_cast<int>(cell);
            // From the sign of d as 0 or 1 rather than ?:, which GCC 12 compiles to a jump a random ray takes
            // either way (d 0, rare, is predicted).
            const int forward = static_cast<int>(d[axis] > 0.0);
            const bool still = d[axis] == 0.0;
            step[axis] = 2 * forward - 1;
            // Cell i's lower face is plane i, its upper face plane i + 1.
            ahead[axis] = tree.gridPlanes_.data() + std::size_t(still ? 3 : axis) * row + std::size_t(forward);
            scale[axis] = still ? 1.0 : inverse[axis];
            next[axis] = planeAhead(axis);
        }
        double t = tEnter;
        bool first = true;
        int previous[3] = {0, 0, 0};
        std::uint32_t current = tree.grid_[gridSlot(std::size_t(index[0]), std::size_t(index[1]), std::size_t(index[2]),
                                                    std::size_t(side))];
        for (;;) {
            const double out = std::min({next[0], next[1], next[2], tExit});
            const int here[3] = {index[0], index[1], index[2]};
            const bool last = out >= tExit;
            std::uint32_t following = 0;
            if (!last) {
                // Every axis: one that is not crossed gets its own plane ahead again, the same double. As out is
                // the least of next[], `<=` is `==` here, and compiles to a flag rather than a jump.
                for (int axis = 0; axis < 3; ++axis) {
                    index[axis] += step[axis] * static_cast<int>(next[axis] <= out);
                    next[axis] = planeAhead(axis);
                }
                following = tree.grid_[gridSlot(std::size_t(index[0]), std::size_t(index[1]), std::size_t(index[2]),
                                                std::size_t(side))];
                if (tree.prefetch_) prefetchCell(tree.cells_[following]);
            }
            if (!tree.gridAbove_.empty()) enterAbove(here, previous, level, first);
            const Cell& cell = tree.cells_[current];
            if (cell.isLeaf()) {
                if (cell.size() > 0) testShapes(cell);
            } else {
                const Point mid(low.x() + (2 * here[0] + 1) * half, low.y() + (2 * here[1] + 1) * half,
                                low.z() + (2 * here[2] + 1) * half);
                visit(current, mid, half, level, t, out);
            }
            if (last || hit.distance < out) return;  // nothing further on can be nearer
            std::copy(here, here + 3, previous);
            first = false;
            t = out;
            current = following;
        }
    }

    void run() {
        if (!d || !p.allFinite()) return;
        const double doubleSlack = kPrefilterSlackRelative * (p.cwiseAbs().maxCoeff() + tree.coordinateScale_);
        // The debugger's record lists every level's cells, so it takes the walk from the root.
        const bool fromGrid = tree.gridLevel_ > 0 && !record;
        if (fromGrid && tree.strictlyInsideRoot(p)) {
            // The common case (a photon inside the scene): the ray enters the root at t = 0, which is what
            // rootSpan gives there. Known without 1 / d, the walk's first cell and the prefilter's ray do not
            // wait on the three divisions, which the processor then overlaps with the first cell's tests.
            prefilterRay.aim(p, d, 0.0, tree.prefilterFrame_, tree.packedReach_, doubleSlack);
            inverse = d.vector().cwiseInverse();
            walkGrid(p, 0.0, tree.rootSpan(p, d, inverse)->second);
            return;
        }
        inverse = d.vector().cwiseInverse();
        const std::optional<std::pair<double, double>> span = tree.rootSpan(p, d, inverse);
        if (!span) return;
        // The prefilter's ray starts where this one enters the root, so its single-precision coordinates are
        // those of points within the frame's unit cube around the root's centre.
        prefilterRay.aim(p, d, span->first, tree.prefilterFrame_, tree.packedReach_, doubleSlack);
        if (fromGrid) {
            Eigen::Vector3d start;
            for (int axis = 0; axis < 3; ++axis) {
                start[axis] = d[axis] == 0.0 ? p[axis] : p[axis] + span->first * d[axis];
            }
            walkGrid(start, span->first, span->second);
        } else {
            visit(0, tree.rootBounds_.center(), tree.rootHalf_, 0, span->first, span->second);
        }
        if (record) record->hit = hit;
    }
};

std::optional<std::pair<double, double>> Octree::rootSpan(const Point& p, const Direction& d) const {
    if (!d || !p.allFinite()) return std::nullopt;
    return rootSpan(p, d, d.vector().cwiseInverse());
}

std::optional<std::pair<double, double>> Octree::rootSpan(const Point& p, const Direction& d,
                                                          const Eigen::Vector3d& inverse) const {
    const CellBounds root = inflatedRoot();
    double tEnter = 0.0;
    double tExit = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (p[axis] < root.min()[axis] || p[axis] > root.max()[axis]) return std::nullopt;
            continue;
        }
        const double t0 = (root.min()[axis] - p[axis]) * inverse[axis];
        const double t1 = (root.max()[axis] - p[axis]) * inverse[axis];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    if (tEnter > tExit) return std::nullopt;
    return std::pair{tEnter, tExit};
}

RayHit Octree::firstHit(const Point& p, const Direction& d) const {
    Traversal traversal{*this, p, d, {}, nullptr, {}, {}};
    traversal.run();
    return traversal.hit;
}

RayHit Octree::firstHit(const Point& p, const Direction& d, TraversalRecord& record) const {
    record = TraversalRecord{};
    Traversal traversal{*this, p, d, {}, &record, {}, {}};
    traversal.run();
    return traversal.hit;
}

}  // namespace dropscope
