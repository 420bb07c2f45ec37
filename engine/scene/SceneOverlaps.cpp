#include "scene/SceneOverlaps.hpp"

#include "geometry/Box.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SpatialHashGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope {

namespace {

using Bounds = Eigen::AlignedBox3d;

// Candidate pairs are those whose bounds, grown by this many surface bands each, intersect. Two shapes
// farther apart than the sum of their bands cannot even touch, so no overlap test could call them
// overlapping; one band each would do, two leave room for the rounding of the bounds themselves.
constexpr double kCandidateBands = 2.0;
// Shapes are sorted into size classes whose widths differ by at most this factor; each class has its
// own grid with cells as wide as its widest shape, so every shape takes one grid entry and a query
// scans a few cells of a class of shapes its size.
constexpr double kSizeClassRatio = 8.0;

// `sphere "d1"`, or just `box` for an unnamed shape.
std::string describe(const Scene& scene, std::size_t id) {
    std::string text = shapeTypeLabel(*scene.shapes[id]);
    if (!scene.shapeNames[id].empty()) text.append(" ").append(jsonpath::quoted(scene.shapeNames[id]));
    return text;
}

// The shapes of one size class, entered in id order as the check goes, so that what a query finds is
// always an earlier shape.
class SizeClass {
public:
    SizeClass(const Bounds& domain, double width, std::size_t count) : grid_(domain, width, count) {
        ids_.reserve(count);
    }

    void add(std::uint32_t id, const Bounds& bounds) {
        grid_.insert(id, bounds, {bounds.center(), 0.5 * bounds.diagonal().norm()});
        ids_.push_back(id);
    }

    // Appends the ids entered so far whose bounds intersect `query` (possibly repeated).
    void collect(const Bounds& query, const std::vector<Bounds>& bounds, std::vector<std::uint32_t>& found) const {
        if (ids_.empty()) return;
        const auto keep = [&](std::uint32_t id) {
            if (bounds[id].intersects(query)) found.push_back(id);
        };
        // A query much larger than the class's cells (a glass cell over a fine cloud) would scan more
        // cells than the class has shapes: then a plain pass over the shapes is cheaper.
        if (cellsScanned(query) > static_cast<double>(ids_.size())) {
            std::for_each(ids_.begin(), ids_.end(), keep);
            return;
        }
        grid_.any(query, [&](std::uint32_t id, const SpatialHashGrid::Ball&) {
            keep(id);
            return false;
        });
    }

private:
    // About how many cells SpatialHashGrid::any scans for `query` (an estimate: it only picks a strategy).
    double cellsScanned(const Bounds& query) const {
        double cells = 1.0;
        for (int axis = 0; axis < 3; ++axis) {
            cells *= std::floor((query.max()[axis] - query.min()[axis]) / grid_.cellSize()) + 2.0;
        }
        return cells;
    }

    SpatialHashGrid grid_;
    std::vector<std::uint32_t> ids_;
};

// Shape i's bounds grown by kCandidateBands of its surface band.
std::vector<Bounds> candidateBounds(const Scene& scene) {
    std::vector<Bounds> bounds;
    bounds.reserve(scene.shapes.size());
    for (const auto& shape : scene.shapes) {
        const double grow = kCandidateBands * shape->surfaceBand();
        const Bounds b = shape->bounds();
        bounds.emplace_back(b.min().array() - grow, b.max().array() + grow);
    }
    return bounds;
}

// The size classes and, for each shape, its class: class k holds widths in
// [smallest * ratio^k, smallest * ratio^(k+1)).
std::vector<SizeClass> sizeClasses(const std::vector<Bounds>& bounds, std::vector<std::size_t>& classOf) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const Bounds& b : bounds) smallest = std::min(smallest, b.sizes().maxCoeff());
    classOf.resize(bounds.size());
    std::vector<Bounds> domains;
    std::vector<double> widths;
    std::vector<std::size_t> counts;
    for (std::size_t id = 0; id < bounds.size(); ++id) {
        const double width = bounds[id].sizes().maxCoeff();
        const auto k =
            static_cast<std::size_t>(std::max(0.0, std::floor(std::log(width / smallest) / std::log(kSizeClassRatio))));
        if (k >= domains.size()) {
            domains.resize(k + 1);
            widths.resize(k + 1, 0.0);
            counts.resize(k + 1, 0);
        }
        domains[k].extend(bounds[id]);
        widths[k] = std::max(widths[k], width);
        ++counts[k];
        classOf[id] = k;
    }
    std::vector<SizeClass> classes;
    classes.reserve(domains.size());
    for (std::size_t k = 0; k < domains.size(); ++k) {
        // An empty class gets a dummy domain; nothing is ever entered in it.
        const bool empty = domains[k].isEmpty();
        classes.emplace_back(empty ? Bounds(Point::Zero(), Point::Ones()) : domains[k], empty ? 1.0 : widths[k],
                             counts[k]);
    }
    return classes;
}

}  // namespace

bool nestsInside(const Shape& inner, const Shape& outer) {
    if (outer.kind() == ShapeKind::Box) return static_cast<const Box&>(outer).encloses(inner);
    if (outer.kind() == ShapeKind::Sphere && inner.kind() == ShapeKind::Sphere) {
        const auto& big = static_cast<const Sphere&>(outer);
        const auto& small = static_cast<const Sphere&>(inner);
        // Touching from inside is allowed, within the outer sphere's surface band.
        return (big.center() - small.center()).norm() + small.radius() <= big.radius() + big.surfaceBand();
    }
    return false;
}

// The pairwise rule of the O(N^2) definition (for each later shape in id order, each earlier one in id
// order), tested only on pairs whose grown bounds meet: shapes are entered into per-size-class hash
// grids in id order, and each one looks up the earlier shapes near it before it is entered itself.
// The first later shape with a partial overlap is reported with its lowest-id partner, as before.
void checkShapesDisjoint(const Scene& scene) {
    const std::vector<Bounds> bounds = candidateBounds(scene);
    std::vector<std::size_t> classOf;
    std::vector<SizeClass> classes = sizeClasses(bounds, classOf);
    std::vector<std::uint32_t> candidates;
    for (std::size_t later = 0; later < scene.shapes.size(); ++later) {
        const Shape& b = *scene.shapes[later];
        candidates.clear();
        for (const SizeClass& sizeClass : classes) sizeClass.collect(bounds[later], bounds, candidates);
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (const std::uint32_t earlier : candidates) {
            const Shape& a = *scene.shapes[earlier];
            if (!a.overlaps(b) || nestsInside(a, b) || nestsInside(b, a)) continue;
            throw SceneError(scene.origin, jsonpath::element("shapes", later),
                             describe(scene, later) + " overlaps " + jsonpath::element("shapes", earlier) + " (" +
                                 describe(scene, earlier) +
                                 "); shapes may touch or nest (anything in a box, a sphere in a sphere), "
                                 "not partly overlap");
        }
        classes[classOf[later]].add(static_cast<std::uint32_t>(later), bounds[later]);
    }
}

}  // namespace dropscope
