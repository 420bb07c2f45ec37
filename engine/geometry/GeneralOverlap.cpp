#include "geometry/GeneralShape.hpp"
#include "geometry/Overlap.hpp"

namespace dropscope {

namespace {

// A box of positive volume around a cover cell (a cell on a flat face can be flat).
Eigen::AlignedBox3d solidCell(const Eigen::AlignedBox3d& cell, double band) {
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(band);
    return {cell.min() - grow, cell.max() + grow};
}

// Some cover cell of `general` may meet `other`.
bool coverMeets(const GeneralShape& general, const Shape& other) {
    const Eigen::AlignedBox3d reach = other.bounds();
    const double band = general.surfaceBand();
    return general.anyCoverBox([&](const Eigen::AlignedBox3d& cell) {
        const Eigen::AlignedBox3d solid = solidCell(cell, band);
        return solid.intersects(reach) && other.mayMeetBox(solid);
    });
}

}  // namespace

// Conservative (docs/general-shapes.md, "Overlaps"): a general shape's surface lies in the union of its
// cover cells. When no cell of either general shape may meet the other shape, neither surface enters the
// other body, so every connected piece of each is wholly inside or wholly outside the other; a piece
// inside would have put its cells inside the other body, which mayMeetBox reports. What remains is a
// box, sphere or ellipsoid (one convex piece) wholly inside a general shape: its centre decides.
bool generalShapesOverlap(const Shape& a, const Shape& b) {
    if (!a.bounds().intersects(b.bounds())) return false;
    const GeneralShape* generalA = asGeneralShape(a);
    const GeneralShape* generalB = asGeneralShape(b);
    if (generalA && coverMeets(*generalA, b)) return true;
    if (generalB && coverMeets(*generalB, a)) return true;
    if (generalA && !generalB) return generalA->locatePoint(b.bounds().center()) != PointLocation::Outside;
    if (generalB && !generalA) return generalB->locatePoint(a.bounds().center()) != PointLocation::Outside;
    return false;
}

}  // namespace dropscope
