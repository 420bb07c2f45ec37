#include "geometry/Box.hpp"

#include "geometry/Tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace dropscope {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

Box::Box(const Point& lower, const Point& upper)
    : lower_(lower),
      upper_(upper),
      band_(tolerance::surfaceBand((upper - lower).maxCoeff(),
                                   std::max(lower.cwiseAbs().maxCoeff(), upper.cwiseAbs().maxCoeff()))) {
    if (!lower.allFinite() || !upper.allFinite()) throw std::invalid_argument("box corners must be finite");
    if (!(lower.array() < upper.array()).all())
        throw std::invalid_argument("box min must be < max in every coordinate");
}

double Box::surfaceArea() const {
    const Eigen::Vector3d e = edgeLengths();
    return 2.0 * (e.x() * e.y() + e.x() * e.z() + e.y() * e.z());  // seed 1.1.2
}

double Box::volume() const { return edgeLengths().prod(); }  // seed 1.1.3

PointLocation Box::locatePoint(const Point& p) const {
    if (!p.allFinite()) return PointLocation::Outside;
    bool onFace = false;
    for (int i = 0; i < 3; ++i) {
        if (p[i] < lower_[i] - band_ || p[i] > upper_[i] + band_) return PointLocation::Outside;
        onFace = onFace || std::abs(p[i] - lower_[i]) <= band_ || std::abs(p[i] - upper_[i]) <= band_;
    }
    return onFace ? PointLocation::OnSurface : PointLocation::Inside;  // seed 1.1.4, 1.1.5
}

bool Box::encloses(const Shape& other) const {  // seed 1.1.9
    return lower_.x() <= other.xMin() && lower_.y() <= other.yMin() && lower_.z() <= other.zMin() &&
           upper_.x() >= other.xMax() && upper_.y() >= other.yMax() && upper_.z() >= other.zMax();
}

bool Box::sameFormAs(const Shape& other) const {
    const auto* box = dynamic_cast<const Box*>(&other);
    if (!box) return false;
    const Eigen::Vector3d a = edgeLengths();
    const Eigen::Vector3d b = box->edgeLengths();
    return (a - b).cwiseAbs().maxCoeff() <= tolerance::kMovedEdgeRelative * a.maxCoeff();
}

// Distance to the nearest face plane the ray leaves through (seed eq. 1.1, its sign corrected:
// docs/geometry.md); from inside the box the exit point is on the box, so the bound checks 1.2-1.3 hold
// by construction.
double Box::exitDistance(const Point& p, const Direction& d) const {
    double exit = kInfinity;
    for (int i = 0; i < 3; ++i) {
        if (d[i] > 0.0) exit = std::min(exit, (upper_[i] - p[i]) / d[i]);
        if (d[i] < 0.0) exit = std::min(exit, (lower_[i] - p[i]) / d[i]);
    }
    return exit;
}

// Slab intersection from outside: the largest entry distance, provided it comes before every exit
// by more than the band (a ray sliding along a face or clipping an edge only touches the box).
double Box::entryDistance(const Point& p, const Direction& d) const {
    double entry = -kInfinity;
    double exit = kInfinity;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (p[i] <= lower_[i] + band_ || p[i] >= upper_[i] - band_) return kNaN;
            continue;
        }
        const double t0 = (lower_[i] - p[i]) / d[i];
        const double t1 = (upper_[i] - p[i]) / d[i];
        entry = std::max(entry, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    if (entry <= 0.0 || exit - entry <= band_) return kNaN;
    return entry;
}

double Box::distanceToSurface(const Point& p, const Direction& d) const {
    if (!d || !p.allFinite()) return kNaN;
    switch (locatePoint(p)) {
    case PointLocation::Inside: return exitDistance(p, d);
    case PointLocation::OnSurface: {
        for (int i = 0; i < 3; ++i) {  // the seed's six "travelling away" conditions (1.1.7)
            if (std::abs(p[i] - lower_[i]) <= band_ && d[i] <= 0.0) return 0.0;
            if (std::abs(p[i] - upper_[i]) <= band_ && d[i] >= 0.0) return 0.0;
        }
        const double farSide = exitDistance(p, d);
        return farSide > band_ ? farSide : 0.0;
    }
    case PointLocation::Outside: return entryDistance(p, d);
    }
    return kNaN;
}

Direction Box::normal(const Point& p) const {  // seed 1.1.8
    if (!surfaceContains(p)) return Direction::invalid();
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    int faces = 0;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(p[i] - lower_[i]) <= band_) {
            n[i] = -1.0;
            ++faces;
        }
        if (std::abs(p[i] - upper_[i]) <= band_) {
            n[i] = 1.0;
            ++faces;
        }
    }
    return faces == 1 ? Direction(n) : Direction::invalid();  // undefined on edges and vertices
}

void Box::print(std::ostream& os) const {
    os << "Box(min=";
    printPoint(os, lower_) << ", max=";
    printPoint(os, upper_) << ')';
}

}  // namespace dropscope
