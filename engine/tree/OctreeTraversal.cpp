// Front-to-back ray traversal of the octree (docs/octree.md, "First hit").
#include "tree/Octree.hpp"

#include <algorithm>
#include <cmath>
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

    // Ray parameter at which it crosses the plane x_axis = value; +inf when parallel to it.
    double crossing(int axis, double value) const {
        return d[axis] == 0.0 ? kInfinity : (value - p[axis]) * inverse[axis];
    }

    void testShapes(const Node& node) {
        for (std::size_t k = 0; k < node.spheres.size(); ++k) {
            hit.offer(node.sphereIds[k], node.spheres[k].distanceToSurface(p, d));
        }
        for (ShapeId id : node.otherIds) hit.offer(id, tree.shapes_[id]->distanceToSurface(p, d));
        if (record) {
            record->shapesTested.insert(record->shapesTested.end(), node.sphereIds.begin(), node.sphereIds.end());
            record->shapesTested.insert(record->shapesTested.end(), node.otherIds.begin(), node.otherIds.end());
            record->distanceEvaluations += node.size();
        }
    }

    // Visits the cell over [tEnter, tExit], then its children in the order the ray meets them,
    // stopping as soon as the best hit lies before the next child's entry.
    void visit(std::uint32_t index, const CellBounds& bounds, double tEnter, double tExit) {
        const Node& node = tree.nodes_[index];
        if (record) record->cells.push_back({index, static_cast<int>(node.level), bounds, tEnter, tExit, node.isLeaf()});
        testShapes(node);
        if (node.isLeaf()) return;

        const Point mid = bounds.center();
        double planeCrossing[3];
        int child = 0;
        for (int axis = 0; axis < 3; ++axis) {
            planeCrossing[axis] = crossing(axis, mid[axis]);
            // The half the ray is in at tEnter: the far half along d once it has crossed the mid-plane.
            const bool upper = d[axis] == 0.0 ? p[axis] >= mid[axis]
                                              : (planeCrossing[axis] <= tEnter) == (d[axis] > 0.0);
            child |= (upper ? 1 : 0) << axis;
        }
        double t = tEnter;
        while (true) {
            double next = tExit;
            for (int axis = 0; axis < 3; ++axis) {
                if (planeCrossing[axis] > t) next = std::min(next, planeCrossing[axis]);
            }
            if (hit.distance < t) return;
            const std::uint32_t first = node.firstChild;
            visit(first + static_cast<std::uint32_t>(child), tree.childBounds(bounds, child), t, next);
            if (next >= tExit) return;
            for (int axis = 0; axis < 3; ++axis) {
                if (planeCrossing[axis] == next) child ^= 1 << axis;
            }
            t = next;
        }
    }

    void run() {
        if (!d || !p.allFinite()) return;
        inverse = d.vector().cwiseInverse();
        // The inflated root: no stored shape reaches beyond it.
        const CellBounds root(tree.rootBounds_.min().array() - tree.margin_,
                              tree.rootBounds_.max().array() + tree.margin_);
        double tEnter = 0.0;
        double tExit = kInfinity;
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0.0) {
                if (p[axis] < root.min()[axis] || p[axis] > root.max()[axis]) return;
                continue;
            }
            const double t0 = crossing(axis, root.min()[axis]);
            const double t1 = crossing(axis, root.max()[axis]);
            tEnter = std::max(tEnter, std::min(t0, t1));
            tExit = std::min(tExit, std::max(t0, t1));
        }
        if (tEnter > tExit) return;
        visit(0, tree.rootBounds_, tEnter, tExit);
        if (record) record->hit = hit;
    }
};

RayHit Octree::firstHit(const Point& p, const Direction& d) const {
    Traversal traversal{*this, p, d, {}, nullptr, {}};
    traversal.run();
    return traversal.hit;
}

RayHit Octree::firstHit(const Point& p, const Direction& d, TraversalRecord& record) const {
    record = TraversalRecord{};
    Traversal traversal{*this, p, d, {}, &record, {}};
    traversal.run();
    return traversal.hit;
}

}  // namespace dropscope
