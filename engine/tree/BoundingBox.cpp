#include "tree/BoundingBox.hpp"

#include <algorithm>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace dropscope {

namespace {

// Whether the half-line p + t d, t >= 0, meets the closed box [lower - margin, upper + margin].
bool rayMeetsBox(const Point& p, const Direction& d, const Point& lower, const Point& upper, double margin) {
    double tEnter = 0.0;
    double tExit = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const double lo = lower[i] - margin;
        const double hi = upper[i] + margin;
        if (d[i] == 0.0) {
            if (p[i] < lo || p[i] > hi) return false;
            continue;
        }
        const double t0 = (lo - p[i]) / d[i];
        const double t1 = (hi - p[i]) / d[i];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    return tEnter <= tExit;
}

}  // namespace

void BoundingBox::addChild(std::unique_ptr<Shape> child, ShapeId terminalId) {
    if (children_.size() >= kMaxChildren) throw std::length_error("a BoundingBox holds at most 8 children");
    children_.push_back(std::move(child));
    childIds_.push_back(terminalId);
}

bool BoundingBox::contentsOverlap(const Shape& other) const {
    for (std::size_t k = 0; k < children_.size(); ++k) {
        if (childIds_[k] != kNotTerminal) {
            if (children_[k]->overlaps(other)) return true;
        } else if (static_cast<const BoundingBox&>(*children_[k]).contentsOverlap(other)) {
            return true;
        }
    }
    return false;
}

RayHit BoundingBox::firstHit(const Point& p, const Direction& d, double margin) const {
    RayHit hit;
    if (d && p.allFinite()) collectHits(p, d, margin, hit);
    return hit;
}

void BoundingBox::collectHits(const Point& p, const Direction& d, double margin, RayHit& hit) const {
    if (!rayMeetsBox(p, d, lower(), upper(), margin)) return;
    for (std::size_t k = 0; k < children_.size(); ++k) {
        if (childIds_[k] != kNotTerminal) {
            hit.offer(childIds_[k], children_[k]->distanceToSurface(p, d));
        } else {
            static_cast<const BoundingBox&>(*children_[k]).collectHits(p, d, margin, hit);
        }
    }
}

std::unique_ptr<Shape> BoundingBox::clone() const {
    auto copy = std::make_unique<BoundingBox>(lower(), upper());
    for (std::size_t k = 0; k < children_.size(); ++k) copy->addChild(children_[k]->clone(), childIds_[k]);
    return copy;
}

void BoundingBox::print(std::ostream& os) const {
    os << "BoundingBox(min=";
    printPoint(os, lower()) << ", max=";
    printPoint(os, upper()) << ", children=" << children_.size() << ')';
}

}  // namespace dropscope
