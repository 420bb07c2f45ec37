#include "geometry/Box.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Overlap.hpp"

namespace dropscope {

// Conservative (docs/geometry.md, "Overlap of parametric and implicit shapes"): the general shape's
// surface lies in the union of its cover boxes. If no cover box meets the other shape's volume, the
// surface is outside the other shape, so the two overlap only if the other lies wholly inside the general
// shape, which one point of its surface decides. A cover box that meets the other shape counts as an
// overlap: shapes closer than the cover's resolution are refused, never shapes that truly overlap accepted.
bool generalShapeOverlaps(const GeneralShape& general, const Shape& other) {
    if (!general.bounds().intersects(other.bounds())) return false;
    const Eigen::AlignedBox3d reach = other.bounds();
    for (const Eigen::AlignedBox3d& cell : general.surfaceCover()) {
        if (!cell.intersects(reach)) continue;
        // Grown by the surface band: points within it are on the surface, and a flat cell gets a volume.
        const Eigen::Vector3d band = Eigen::Vector3d::Constant(general.surfaceBand());
        const Box box(cell.min() - band, cell.max() + band);
        if (shapesOverlap(box, other)) return true;
    }
    // Any point of the other shape: the centre of a box, sphere or ellipsoid; a surface point otherwise.
    const GeneralShape* otherGeneral = asGeneralShape(other);
    const Point inOther = otherGeneral ? otherGeneral->surfacePoint() : other.bounds().center();
    return general.locatePoint(inOther) == PointLocation::Inside;
}

}  // namespace dropscope
