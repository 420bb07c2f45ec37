#include "geometry/Overlap.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Sphere.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dropscope {

bool boxesOverlap(const Box& a, const Box& b) {  // seed 1.1.6, by more than both bands on every axis
    const double band = a.surfaceBand() + b.surfaceBand();
    for (int i = 0; i < 3; ++i) {
        const double shared = std::min(a.upper()[i], b.upper()[i]) - std::max(a.lower()[i], b.lower()[i]);
        if (shared <= band) return false;
    }
    return true;
}

bool spheresOverlap(const Sphere& a, const Sphere& b) {  // seed eq. 1.6
    const double reach = a.radius() + b.radius() - a.surfaceBand() - b.surfaceBand();
    return (a.center() - b.center()).norm() < reach;
}

bool sphereOverlapsBox(const Sphere& sphere, const Box& box) {
    // seed eq. 1.8: the point of the box closest to the centre
    const Point closest = sphere.center().cwiseMax(box.lower()).cwiseMin(box.upper());
    return (sphere.center() - closest).norm() < sphere.radius() - sphere.surfaceBand() - box.surfaceBand();  // eq. 1.7
}

namespace {

// Pairs arrive in ShapeKind order (a.kind() <= b.kind()), so every test is written once and is symmetric.
bool orderedOverlap(const Shape& a, const Shape& b) {
    const auto& box = [](const Shape& s) -> const Box& { return static_cast<const Box&>(s); };
    const auto& sphere = [](const Shape& s) -> const Sphere& { return static_cast<const Sphere&>(s); };
    const auto& ellipsoid = [](const Shape& s) -> const Ellipsoid& { return static_cast<const Ellipsoid&>(s); };
    switch (a.kind()) {
    case ShapeKind::Box:
        switch (b.kind()) {
        case ShapeKind::Box: return boxesOverlap(box(a), box(b));
        case ShapeKind::Sphere: return sphereOverlapsBox(sphere(b), box(a));
        case ShapeKind::Ellipsoid: return ellipsoidOverlapsBox(ellipsoid(b), box(a));
        case ShapeKind::Parametric:
        case ShapeKind::Implicit: break;
        }
        break;
    case ShapeKind::Sphere:
        switch (b.kind()) {
        case ShapeKind::Sphere: return spheresOverlap(sphere(a), sphere(b));
        case ShapeKind::Ellipsoid: return ellipsoidOverlapsSphere(ellipsoid(b), sphere(a));
        case ShapeKind::Box:
        case ShapeKind::Parametric:
        case ShapeKind::Implicit: break;
        }
        break;
    case ShapeKind::Ellipsoid:
        if (b.kind() == ShapeKind::Ellipsoid) return ellipsoidsOverlap(ellipsoid(a), ellipsoid(b));
        break;
    case ShapeKind::Parametric:
    case ShapeKind::Implicit: break;
    }
    throw std::logic_error("no overlap test between a " + std::string(a.typeName()) + " and a " +
                           std::string(b.typeName()));
}

}  // namespace

bool shapesOverlap(const Shape& a, const Shape& b) {
    if (asGeneralShape(a) || asGeneralShape(b)) return generalShapesOverlap(a, b);
    return a.kind() <= b.kind() ? orderedOverlap(a, b) : orderedOverlap(b, a);
}

}  // namespace dropscope
