#include "tree/Octree.hpp"

#include "geometry/Sphere.hpp"
#include "tree/BoundingBox.hpp"

#include <algorithm>
#include <stdexcept>

namespace dropscope {

namespace {

// Cells are inflated by this fraction of the root's diagonal when deciding where a shape is stored.
// It must exceed the rounding of the traversal's crossing points (~1e-16 of the coordinates) and
// every shape's surface band (1e-9 of its size), and costs only a few extra shapes per cell.
constexpr double kMarginRelative = 1e-8;

CellBounds boundsOf(const Shape& s) {
    return CellBounds(Point(s.xMin(), s.yMin(), s.zMin()), Point(s.xMax(), s.yMax(), s.zMax()));
}

CellBounds inflated(const CellBounds& b, double by) {
    return CellBounds(b.min().array() - by, b.max().array() + by);
}

// A cube around all the shapes, so that cells are cubes too.
CellBounds cubeAround(const std::vector<std::unique_ptr<Shape>>& shapes, const CellBounds& mustContain) {
    CellBounds all = mustContain;
    for (const auto& s : shapes) {
        if (s) all.extend(boundsOf(*s));
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

}  // namespace

Octree::Octree(std::vector<std::unique_ptr<Shape>> shapes, OctreeSettings settings)
    : shapes_(std::move(shapes)), settings_(settings) {
    if (settings_.maxDepth < 0 || settings_.maxDepth > 30) throw std::invalid_argument("octree max_depth must be in 0..30");
    if (settings_.maxShapesPerLeaf < 1) throw std::invalid_argument("octree max_shapes_per_leaf must be >= 1");
    rebuild(cubeAround(shapes_, CellBounds()));
}

Octree::~Octree() = default;
Octree::Octree(Octree&&) noexcept = default;
Octree& Octree::operator=(Octree&&) noexcept = default;

void Octree::rebuild(const CellBounds& bounds) {
    rootBounds_ = bounds;
    margin_ = std::max(kMarginRelative * bounds.diagonal().norm(), 4.0 * largestBand(shapes_));
    nodes_.assign(1, Node{});
    liveShapes_ = 0;
    for (std::size_t id = 0; id < shapes_.size(); ++id) {
        if (!shapes_[id]) continue;
        ++liveShapes_;
        place(0, rootBounds_, static_cast<ShapeId>(id));
    }
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

// Conservative: the shape's extent meets the inflated cell, and its exact overlap test agrees.
bool Octree::reaches(const Shape& shape, const CellBounds& cell) const {
    const CellBounds grown = inflated(cell, margin_);
    if (!grown.intersects(boundsOf(shape))) return false;
    return shape.overlaps(Box(grown.min(), grown.max()));
}

void Octree::store(Node& node, ShapeId id) {
    const Shape& s = *shapes_[id];
    if (s.kind() == ShapeKind::Sphere) {
        node.spheres.push_back(static_cast<const Sphere&>(s).geometry());
        node.sphereIds.push_back(id);
    } else {
        node.otherIds.push_back(id);
    }
}

void Octree::place(std::uint32_t node, const CellBounds& bounds, ShapeId id) {
    if (nodes_[node].isLeaf()) {
        store(nodes_[node], id);
        if (static_cast<int>(nodes_[node].size()) > settings_.maxShapesPerLeaf &&
            static_cast<int>(nodes_[node].level) < settings_.maxDepth) {
            split(node, bounds);
        }
        return;
    }
    const Shape& s = *shapes_[id];
    int reached[8];
    int count = 0;
    for (int child = 0; child < 8; ++child) {
        if (reaches(s, childBounds(bounds, child))) reached[count++] = child;
    }
    if (count == 8) {
        store(nodes_[node], id);
        return;
    }
    const std::uint32_t first = nodes_[node].firstChild;
    for (int k = 0; k < count; ++k) place(first + static_cast<std::uint32_t>(reached[k]), childBounds(bounds, reached[k]), id);
}

// Turns a full leaf into an inner cell and hands its shapes down (those reaching all 8 children stay).
void Octree::split(std::uint32_t node, const CellBounds& bounds) {
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    const std::uint32_t level = nodes_[node].level + 1;
    nodes_.resize(nodes_.size() + 8);
    for (std::uint32_t k = 0; k < 8; ++k) nodes_[first + k].level = level;
    Node& parent = nodes_[node];
    std::vector<ShapeId> ids = parent.sphereIds;
    ids.insert(ids.end(), parent.otherIds.begin(), parent.otherIds.end());
    parent = Node{};
    parent.firstChild = first;
    parent.level = level - 1;
    std::sort(ids.begin(), ids.end());  // children then list shapes in id order
    for (ShapeId id : ids) place(node, bounds, id);
}

ShapeId Octree::insert(std::unique_ptr<Shape> shape) {
    if (!shape) throw std::invalid_argument("Octree::insert: null shape");
    const auto id = static_cast<ShapeId>(shapes_.size());
    const CellBounds extent = boundsOf(*shape);
    const double band = shape->surfaceBand();
    shapes_.push_back(std::move(shape));
    if (!rootBounds_.contains(extent) || 4.0 * band > margin_) {
        rebuild(cubeAround(shapes_, rootBounds_));  // outside the root: grow it
        return id;
    }
    ++liveShapes_;
    place(0, rootBounds_, id);
    return id;
}

void Octree::unstore(std::uint32_t node, const CellBounds& bounds, ShapeId id) {
    Node& n = nodes_[node];
    const auto sphere = std::find(n.sphereIds.begin(), n.sphereIds.end(), id);
    if (sphere != n.sphereIds.end()) {
        n.spheres.erase(n.spheres.begin() + (sphere - n.sphereIds.begin()));
        n.sphereIds.erase(sphere);
    }
    n.otherIds.erase(std::remove(n.otherIds.begin(), n.otherIds.end(), id), n.otherIds.end());
    if (n.isLeaf()) return;
    const CellBounds extent = inflated(boundsOf(*shapes_[id]), margin_);
    for (int child = 0; child < 8; ++child) {
        const CellBounds cb = childBounds(bounds, child);
        if (cb.intersects(extent)) unstore(n.firstChild + static_cast<std::uint32_t>(child), cb, id);
    }
}

std::unique_ptr<Shape> Octree::remove(ShapeId id) {
    if (id >= shapes_.size() || !shapes_[id]) throw std::out_of_range("Octree::remove: no shape " + std::to_string(id));
    unstore(0, rootBounds_, id);
    --liveShapes_;
    return std::move(shapes_[id]);
}

std::vector<LevelStatistics> Octree::statistics() const {
    std::vector<LevelStatistics> levels;
    forEachNode([&](std::uint32_t, const Node& n, const CellBounds&) {
        if (levels.size() <= n.level) levels.resize(n.level + 1);
        LevelStatistics& s = levels[n.level];
        s.level = static_cast<int>(n.level);
        ++s.cells;
        s.shapesStored += n.size();
        s.bytes += sizeof(Node) + n.spheres.capacity() * sizeof(SphereGeometry) +
                   (n.sphereIds.capacity() + n.otherIds.capacity()) * sizeof(ShapeId);
        if (!n.isLeaf()) return true;
        ++s.leaves;
        if (s.shapesPerLeaf.size() <= n.size()) s.shapesPerLeaf.resize(n.size() + 1);
        ++s.shapesPerLeaf[n.size()];
        return true;
    });
    return levels;
}

std::size_t Octree::bytesUsed() const {
    std::size_t bytes = sizeof(*this) + (nodes_.capacity() - nodes_.size()) * sizeof(Node);
    for (const LevelStatistics& level : statistics()) bytes += level.bytes;
    return bytes + shapes_.capacity() * sizeof(std::unique_ptr<Shape>);
}

}  // namespace dropscope
