#include "geometry/Shape.hpp"

#include "geometry/Overlap.hpp"

#include <ostream>
#include <stdexcept>
#include <string>

namespace dropscope {

Eigen::AlignedBox3d Shape::bounds() const {
    return Eigen::AlignedBox3d(Point(xMin(), yMin(), zMin()), Point(xMax(), yMax(), zMax()));
}

bool Shape::overlaps(const Shape& other) const { return shapesOverlap(*this, other); }

std::ostream& operator<<(std::ostream& os, const Shape& shape) {
    shape.print(os);
    return os;
}

}  // namespace dropscope
