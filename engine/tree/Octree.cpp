#include "tree/Octree.hpp"

#include "geometry/Sphere.hpp"
#include "tree/BoundingBox.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dropscope {

namespace {

// Cells are inflated by this fraction of the root's diagonal when deciding where a shape is stored.
// It must exceed the rounding of the traversal's crossing points (~1e-16 of the coordinates) and
// every shape's surface band (1e-9 of its size), and costs only a few extra shapes per cell.
constexpr double kMarginRelative = 1e-8;

// Sphere blocks beyond this many bytes are mostly out of cache when a ray reaches them, and the traversal
// prefetches a cell's children; below it the data are cached and prefetching is only extra instructions
// (docs/performance.md, measured with blocks of doubles: nothing measurable gained at 1e3-1e4 droplets,
// 0.05-0.5 MB; leaving it out at 1e6, 46 MB, cost up to a quarter of random-ray throughput; prefetching from
// 1 MiB cost 7-10 % at 1e5). 8 MiB: a few times a core's L2, inside L3. The float blocks, half the bytes
// (2.2 MB at 1e5, 22 MB at 1e6), fall on the same sides of it.
constexpr std::size_t kPrefetchBytes = std::size_t{8} << 20;

// Sphere blocks up to this many bytes (a core's L2 here) let the prefilter read on past a cell's own blocks
// (sphereCandidates' readAhead): in cache, the extra lanes cost less than a mispredicted loop end; beyond it they
// would be loads from L3 or memory (0.2 MB of blocks at 1e4 droplets, 2.2 MB at 1e5).
constexpr std::size_t kReadAheadBytes = std::size_t{1} << 20;

// The top grid (docs/octree.md): below level 2 it would skip at most the root's visit; above level 6 its
// table (8^level cell indices) would pass 1 MiB, and in a tree that deep the levels below the grid are
// few against those it skips.
constexpr int kMinGridLevel = 2;
constexpr int kMaxGridLevel = 6;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

CellBounds inflated(const CellBounds& b, double by) { return CellBounds(b.min().array() - by, b.max().array() + by); }

// Whether a sphere reaches an inflated cell (Octree::reaches): the cell's point nearest its centre is within it.
bool sphereReaches(const Point& center, double radius, const CellBounds& grown) {
    const Point closest = center.cwiseMax(grown.min()).cwiseMin(grown.max());
    return (closest - center).squaredNorm() < radius * radius;
}

// A cube around all the shapes, so that cells are cubes too.
CellBounds cubeAround(const std::vector<std::unique_ptr<Shape>>& shapes, const CellBounds& mustContain) {
    CellBounds all = mustContain;
    for (const auto& s : shapes) {
        if (s) all.extend(s->bounds());
    }
    if (all.isEmpty()) all = CellBounds(Point::Constant(-1.0), Point::Constant(1.0));
    const double half = 0.5 * all.sizes().maxCoeff() * (1.0 + 1e-6) + 1e-300;
    return CellBounds(all.center().array() - half, all.center().array() + half);
}

double largestBand(const std::vector<std::unique_ptr<Shape>>& shapes) {
    double band = 0.0;
    for (const auto& s : shapes) {
        if (s) band = std::max(band, s->surfaceBand());
    }
    return band;
}

// Interleaves the bits of three 21-bit coordinates.
std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    const auto spread = [](std::uint64_t v) {
        v &= 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffffULL;
        v = (v | v << 16) & 0x1f0000ff0000ffULL;
        v = (v | v << 8) & 0x100f00f00f00f00fULL;
        v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
        v = (v | v << 2) & 0x1249249249249249ULL;
        return v;
    };
    return spread(x) | spread(y) << 1 | spread(z) << 2;
}

}  // namespace

Octree::Octree(std::vector<std::unique_ptr<Shape>> shapes, OctreeSettings settings, OctreeBuild build)
    : shapes_(std::move(shapes)), settings_(settings), build_(build) {
    if (settings_.maxDepth < 0 || settings_.maxDepth > 30)
        throw std::invalid_argument("octree max_depth must be in 0..30");
    if (settings_.maxShapesPerLeaf < 1) throw std::invalid_argument("octree max_shapes_per_leaf must be >= 1");
    rebuild(cubeAround(shapes_, CellBounds()));
}

Octree::~Octree() = default;
Octree::Octree(Octree&&) noexcept = default;
Octree& Octree::operator=(Octree&&) noexcept = default;

void Octree::rebuild(const CellBounds& bounds) {
    rootBounds_ = bounds;
    margin_ = std::max(kMarginRelative * bounds.diagonal().norm(), 4.0 * largestBand(shapes_));
    building_.assign(1, Node{});
    liveShapes_ = 0;
    // In Morton order of their centres: placed one by one, consecutive shapes then walk the same cells, which
    // stay in cache. The tree's cells do not depend on the order, but each cell keeps its shapes in it.
    std::vector<std::pair<std::uint64_t, ShapeId>> order;
    order.reserve(shapes_.size());
    const Eigen::Array3d scale = 2097151.0 / rootBounds_.sizes().array();  // 21 bits per axis
    for (std::size_t id = 0; id < shapes_.size(); ++id) {
        if (!shapes_[id]) continue;
        const Eigen::Array3d cell =
            ((shapes_[id]->bounds().center() - rootBounds_.min()).array() * scale).max(0.0).min(2097151.0);
        order.emplace_back(mortonCode(static_cast<std::uint32_t>(cell.x()), static_cast<std::uint32_t>(cell.y()),
                                      static_cast<std::uint32_t>(cell.z())),
                           static_cast<ShapeId>(id));
    }
    std::sort(order.begin(), order.end());
    liveShapes_ = order.size();
    if (build_ == OctreeBuild::OneByOne) {
        for (const auto& [code, id] : order) place(0, rootBounds_, id, shapes_[id]->bounds());
        freeze();
        return;
    }
    // Read once, in that order, so that the cells' lists (positions in it, ascending) read them in sequence. (The
    // bounds are worked out again rather than kept from above: a second array of them would add 48 bytes a shape
    // to the build's peak.)
    std::vector<Placing> placing(order.size());
    std::vector<std::uint32_t> positions(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const ShapeId id = order[k].second;
        Placing& shape = placing[k];
        shape.shape = shapes_[id].get();
        shape.extent = shape.shape->bounds();
        shape.id = id;
        shape.sphere = shape.shape->kind() == ShapeKind::Sphere;
        if (shape.sphere) {
            shape.center = static_cast<const Sphere*>(shape.shape)->center();
            shape.radius = static_cast<const Sphere*>(shape.shape)->radius();
        }
        positions[k] = static_cast<std::uint32_t>(k);
    }
    order = {};
    placeTopDown(0, rootBounds_, positions, placing);
    freeze();
}

// A cell is split exactly when more than maxShapesPerLeaf shapes are placed into it (below maxDepth), whatever
// their order, so the cells can be made from the top down: each cell's shapes handed to the children they reach,
// in order, but those reaching all eight, which it keeps. The same tests as place() and reaches(), on the
// shapes' bounds and spheres read once; the children are numbered depth first instead of in the order of the
// splits, which no query depends on.
void Octree::placeTopDown(std::uint32_t node, const CellBounds& bounds, std::vector<std::uint32_t>& positions,
                          const std::vector<Placing>& placing) {
    if (!overflows(positions.size(), building_[node].level)) {
        Node& leaf = building_[node];
        for (const std::uint32_t at : positions) {
            leaf.add(placing[at].id, placing[at].sphere);
        }
        return;
    }
    const std::uint32_t first = addChildren(node);
    Node& inner = building_[node];
    std::array<CellBounds, 8> children;
    std::array<CellBounds, 8> grown;
    for (int child = 0; child < 8; ++child) {
        children[child] = childBounds(bounds, child);
        grown[child] = inflated(children[child], margin_);
    }
    // A grown child's side along each axis is the lower child's (child 0) or the upper one's (child 7), and a box
    // meets it when it meets all three sides (CellBounds::intersects): each side is compared once per shape.
    const CellBounds& lower = grown[0];
    const CellBounds& upper = grown[7];
    std::array<std::vector<std::uint32_t>, 8> lists;
    for (const std::uint32_t at : positions) {
        const Placing& shape = placing[at];
        std::uint32_t meetsLower = 0;
        std::uint32_t meetsUpper = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double low = shape.extent.min()[axis];
            const double high = shape.extent.max()[axis];
            meetsLower |= (lower.min()[axis] <= high && low <= lower.max()[axis] ? 1U : 0U) << axis;
            meetsUpper |= (upper.min()[axis] <= high && low <= upper.max()[axis] ? 1U : 0U) << axis;
        }
        std::uint32_t reached = 0;
        for (std::uint32_t child = 0; child < 8; ++child) {
            if (((child & meetsUpper) | (~child & 7U & meetsLower)) != 7U) continue;
            const CellBounds& cell = grown[child];
            const bool reaches = shape.sphere ? sphereReaches(shape.center, shape.radius, cell)
                                              : shape.shape->overlaps(Box(cell.min(), cell.max()));
            reached |= (reaches ? 1U : 0U) << child;
        }
        if (reached == 0xff) {
            inner.add(shape.id, shape.sphere);
            continue;
        }
        for (int child = 0; child < 8; ++child) {
            if ((reached >> child) & 1U) lists[child].push_back(at);
        }
    }
    positions = {};  // handed down: freed before the children's lists are
    for (std::uint32_t child = 0; child < 8; ++child)
        placeTopDown(first + child, children[child], lists[child], placing);
}

void Octree::freeze() {
    readAheadBefore_ = 0;
    cells_.clear();
    blocks_.clear();
    exactSpheres_.clear();
    sphereIds_.clear();
    others_.clear();
    cells_.reserve(building_.size());
    std::vector<std::pair<ShapeId, const SphereGeometry*>> spheres;
    rootHalf_ = 0.5 * rootBounds_.sizes().maxCoeff();
    prefilterFrame_ = PrefilterFrame::around(rootBounds_.center(), rootHalf_);
    packedReach_ = 0.0;
    for (const Node& node : building_) {
        // A sphere the blocks cannot hold (a band make() would not recompute; too large or too far for single
        // precision; none in any real scene) is kept with the other shapes.
        spheres.clear();
        const auto firstOther = static_cast<std::uint32_t>(others_.size());
        for (ShapeId id : node.sphereIds) {
            const SphereGeometry& sphere = static_cast<const Sphere&>(*shapes_[id]).geometry();
            if (SphereLanes::packable(sphere, prefilterFrame_)) {
                spheres.emplace_back(id, &sphere);
                if (exactSpheres_.empty()) exactSpheres_.resize(shapes_.size());
                exactSpheres_[id] = {sphere.center, sphere.radius};
                packedReach_ = std::max(packedReach_, prefilterFrame_.reach(sphere));
            } else {
                others_.push_back(id);
            }
        }
        others_.insert(others_.end(), node.otherIds.begin(), node.otherIds.end());
        cells_.push_back({node.firstChild, static_cast<std::uint32_t>(blocks_.size()),
                          static_cast<std::uint32_t>(spheres.size()), firstOther,
                          static_cast<std::uint32_t>(others_.size()) - firstOther});
        const auto count = static_cast<unsigned>(spheres.size());
        if (count == 0) continue;
        const std::size_t firstBlock = blocks_.size();
        blocks_.resize(firstBlock + SphereLanes::blocksFor(count));
        SphereLanes lanes(blocks_.data() + firstBlock, count);
        for (unsigned lane = 0; lane < lanes.stride(); ++lane) {
            const bool used = lane < count;
            if (used)
                lanes.pack(lane, *spheres[lane].second, prefilterFrame_);
            else
                lanes.clear(lane);
            sphereIds_.push_back(used ? spheres[lane].first : RayHit::kNone);
        }
    }
    cells_.shrink_to_fit();
    blocks_.shrink_to_fit();
    sphereIds_.shrink_to_fit();
    exactSpheres_.shrink_to_fit();
    others_.shrink_to_fit();
    building_ = {};
    const CellBounds root = inflatedRoot();
    coordinateScale_ = largestCoordinate(root);
    const std::size_t blockBytes = blocks_.size() * sizeof(SphereBlock);
    prefetch_ = blockBytes > kPrefetchBytes;
    constexpr std::size_t kReadAheadBlocks = kPrefilterFixedLanes / SphereBlock::kWidth;
    readAheadBefore_ = blockBytes > kReadAheadBytes || blocks_.size() < kReadAheadBlocks
                           ? 0
                           : static_cast<std::uint32_t>(blocks_.size() - kReadAheadBlocks + 1);
    buildGrid();
}

// The deepest level (up to kMaxGridLevel) above which every cell is an inner cell: its 8^level cells are
// then all present, and a ray can walk them as a uniform grid without visiting the levels above. Inner
// cells may hold shapes (those reaching all 8 children); the levels between the root and the grid are
// kept as tables too when any of them does, so the walk can test them as it enters their cells.
void Octree::buildGrid() {
    gridLevel_ = 0;
    grid_.clear();
    gridAbove_.clear();
    gridPlanes_.clear();
    struct Placed {
        std::uint32_t cell;
        std::uint32_t x, y, z;
    };
    std::vector<std::vector<Placed>> levels{{{0, 0, 0, 0}}};
    while (static_cast<int>(levels.size()) <= kMaxGridLevel) {
        const std::vector<Placed>& level = levels.back();
        const bool allInner = std::none_of(level.begin(), level.end(),
                                           [&](const Placed& placed) { return cells_[placed.cell].isLeaf(); });
        if (!allInner) break;
        std::vector<Placed> children;
        children.reserve(level.size() * 8);
        for (const Placed& placed : level) {
            for (std::uint32_t child = 0; child < 8; ++child) {
                children.push_back({cells_[placed.cell].firstChild + child, 2 * placed.x + (child & 1),
                                    2 * placed.y + ((child >> 1) & 1), 2 * placed.z + ((child >> 2) & 1)});
            }
        }
        levels.push_back(std::move(children));
    }
    const int depth = static_cast<int>(levels.size()) - 1;
    if (depth < kMinGridLevel) return;
    gridLevel_ = depth;
    gridLow_ = rootBounds_.center().array() - rootHalf_;
    gridCell_ = std::ldexp(2.0 * rootHalf_, -depth);
    gridCellInverse_ = 1.0 / gridCell_;
    const std::size_t side = std::size_t{1} << depth;
    gridPlanes_.assign(4 * (side + 1), kInfinity);
    for (int axis = 0; axis < 3; ++axis) {
        double* row = gridPlanes_.data() + static_cast<std::size_t>(axis) * (side + 1);
        row[0] = -kInfinity;
        for (std::size_t i = 1; i < side; ++i) row[i] = gridLow_[axis] + gridCell_ * static_cast<double>(i);
    }
    const auto table = [&](const std::vector<Placed>& level, int at, std::vector<std::uint32_t>& into) {
        const std::size_t levelSide = std::size_t{1} << at;
        const std::size_t offset = into.size();
        into.resize(offset + levelSide * levelSide * levelSide);
        for (const Placed& placed : level) {
            into[offset + gridSlot(placed.x, placed.y, placed.z, levelSide)] = placed.cell;
        }
    };
    table(levels[static_cast<std::size_t>(depth)], depth, grid_);
    grid_.shrink_to_fit();
    bool innerShapes = false;
    for (int at = 1; at < depth; ++at) {
        for (const Placed& placed : levels[static_cast<std::size_t>(at)]) innerShapes |= cells_[placed.cell].size() > 0;
    }
    if (!innerShapes) return;
    for (int at = 1; at < depth; ++at) table(levels[static_cast<std::size_t>(at)], at, gridAbove_);
    gridAbove_.shrink_to_fit();
}

void Octree::thaw() {
    building_.assign(cells_.size(), Node{});
    forEachNode([&](std::uint32_t index, const Cell& cell, const CellBounds&, int level) {
        Node& node = building_[index];
        node.firstChild = cell.firstChild;
        node.level = static_cast<std::uint32_t>(level);
        const ShapeId* ids = sphereIds_.data() + std::size_t{cell.firstBlock} * SphereBlock::kWidth;
        node.sphereIds.assign(ids, ids + cell.sphereCount);
        node.otherIds.assign(others_.begin() + cell.firstOther, others_.begin() + cell.firstOther + cell.otherCount);
        return true;
    });
}

CellBounds Octree::childBounds(const CellBounds& bounds, int child) const {
    const Point mid = bounds.center();
    CellBounds result;
    for (int i = 0; i < 3; ++i) {
        const bool upper = ((child >> i) & 1) != 0;
        result.min()[i] = upper ? mid[i] : bounds.min()[i];
        result.max()[i] = upper ? bounds.max()[i] : mid[i];
    }
    return result;
}

// Conservative: the shape's extent meets the inflated cell, and its exact overlap test agrees. For a
// sphere, the distance from its centre to the inflated cell below its radius (seed eq. 1.7 without
// the bands, which only makes it more inclusive), without building a Box.
bool Octree::reaches(const Shape& shape, const CellBounds& extent, const CellBounds& cell) const {
    const CellBounds grown = inflated(cell, margin_);
    if (!grown.intersects(extent)) return false;
    if (shape.kind() == ShapeKind::Sphere) {
        const auto& sphere = static_cast<const Sphere&>(shape);
        return sphereReaches(sphere.center(), sphere.radius(), grown);
    }
    return shape.overlaps(Box(grown.min(), grown.max()));
}

void Octree::store(Node& node, ShapeId id) const { node.add(id, shapes_[id]->kind() == ShapeKind::Sphere); }

void Octree::place(std::uint32_t node, const CellBounds& bounds, ShapeId id, const CellBounds& extent) {
    if (building_[node].isLeaf()) {
        store(building_[node], id);
        if (overflows(building_[node].size(), building_[node].level)) split(node, bounds);
        return;
    }
    const Shape& s = *shapes_[id];
    int reached[8];
    int count = 0;
    for (int child = 0; child < 8; ++child) {
        if (reaches(s, extent, childBounds(bounds, child))) reached[count++] = child;
    }
    if (count == 8) {
        store(building_[node], id);
        return;
    }
    const std::uint32_t first = building_[node].firstChild;
    for (int k = 0; k < count; ++k) {
        place(first + static_cast<std::uint32_t>(reached[k]), childBounds(bounds, reached[k]), id, extent);
    }
}

// Turns a full leaf into an inner cell and hands its shapes down (those reaching all 8 children stay).
void Octree::split(std::uint32_t node, const CellBounds& bounds) {
    Node& parent = building_[node];
    std::vector<ShapeId> ids = std::move(parent.sphereIds);
    ids.insert(ids.end(), parent.otherIds.begin(), parent.otherIds.end());
    parent.sphereIds.clear();
    parent.otherIds.clear();
    addChildren(node);
    for (ShapeId id : ids) place(node, bounds, id, shapes_[id]->bounds());
}

bool Octree::overflows(std::size_t shapes, std::uint32_t level) const {
    return shapes > static_cast<std::size_t>(settings_.maxShapesPerLeaf) &&
           static_cast<int>(level) < settings_.maxDepth;
}

std::uint32_t Octree::addChildren(std::uint32_t node) {
    const auto first = static_cast<std::uint32_t>(building_.size());
    const std::uint32_t level = building_[node].level + 1;
    building_.resize(building_.size() + 8);
    for (std::uint32_t k = 0; k < 8; ++k) building_[first + k].level = level;
    building_[node].firstChild = first;
    return first;
}

ShapeId Octree::insert(std::unique_ptr<Shape> shape) {
    if (!shape) throw std::invalid_argument("Octree::insert: null shape");
    const auto id = static_cast<ShapeId>(shapes_.size());
    shapes_.emplace_back();
    fillSlot(id, std::move(shape));
    return id;
}

void Octree::insertAt(ShapeId id, std::unique_ptr<Shape> shape) {
    if (!shape) throw std::invalid_argument("Octree::insertAt: null shape");
    if (id >= shapes_.size()) {
        throw std::invalid_argument("Octree::insertAt: no slot " + std::to_string(id) + " (" +
                                    std::to_string(shapes_.size()) + " slots)");
    }
    if (shapes_[id]) throw std::invalid_argument("Octree::insertAt: slot " + std::to_string(id) + " is occupied");
    fillSlot(id, std::move(shape));
}

void Octree::fillSlot(ShapeId id, std::unique_ptr<Shape> shape) {
    const CellBounds extent = shape->bounds();
    const double band = shape->surfaceBand();
    shapes_[id] = std::move(shape);
    if (!rootBounds_.contains(extent) || 4.0 * band > margin_) {
        rebuild(cubeAround(shapes_, rootBounds_));  // outside the root: grow it
        return;
    }
    ++liveShapes_;
    thaw();
    place(0, rootBounds_, id, extent);
    freeze();
}

void Octree::unstore(std::uint32_t node, const CellBounds& bounds, ShapeId id) {
    Node& n = building_[node];
    n.sphereIds.erase(std::remove(n.sphereIds.begin(), n.sphereIds.end(), id), n.sphereIds.end());
    n.otherIds.erase(std::remove(n.otherIds.begin(), n.otherIds.end(), id), n.otherIds.end());
    if (n.isLeaf()) return;
    const CellBounds extent = inflated(shapes_[id]->bounds(), margin_);
    for (int child = 0; child < 8; ++child) {
        const CellBounds cb = childBounds(bounds, child);
        if (cb.intersects(extent)) unstore(n.firstChild + static_cast<std::uint32_t>(child), cb, id);
    }
}

std::unique_ptr<Shape> Octree::remove(ShapeId id) {
    if (id >= shapes_.size() || !shapes_[id]) throw std::out_of_range("Octree::remove: no shape " + std::to_string(id));
    thaw();
    unstore(0, rootBounds_, id);
    freeze();
    --liveShapes_;
    return std::move(shapes_[id]);
}

std::vector<LevelStatistics> Octree::statistics() const {
    std::vector<LevelStatistics> levels;
    forEachNode([&](std::uint32_t, const Cell& cell, const CellBounds&, int level) {
        const auto depth = static_cast<std::size_t>(level);
        if (levels.size() <= depth) levels.resize(depth + 1);
        LevelStatistics& s = levels[depth];
        s.level = level;
        ++s.cells;
        s.shapesStored += cell.size();
        const std::size_t blocks = (cell.sphereCount + SphereBlock::kWidth - 1) / SphereBlock::kWidth;
        s.bytes += sizeof(Cell) + blocks * (sizeof(SphereBlock) + SphereBlock::kWidth * sizeof(ShapeId)) +
                   cell.otherCount * sizeof(ShapeId);
        if (!cell.isLeaf()) return true;
        ++s.leaves;
        if (s.shapesPerLeaf.size() <= cell.size()) s.shapesPerLeaf.resize(cell.size() + 1);
        ++s.shapesPerLeaf[cell.size()];
        return true;
    });
    return levels;
}

std::size_t Octree::bytesUsed() const {
    return sizeof(*this) + cells_.capacity() * sizeof(Cell) + blocks_.capacity() * sizeof(SphereBlock) +
           sphereIds_.capacity() * sizeof(ShapeId) + exactSpheres_.capacity() * sizeof(ExactSphere) +
           others_.capacity() * sizeof(ShapeId) + shapes_.capacity() * sizeof(std::unique_ptr<Shape>) +
           (grid_.capacity() + gridAbove_.capacity()) * sizeof(std::uint32_t) + gridPlanes_.capacity() * sizeof(double);
}

}  // namespace dropscope
