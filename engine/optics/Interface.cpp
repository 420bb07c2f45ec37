#include "optics/Interface.hpp"

#include <cmath>

namespace dropscope {

Refraction refract(const Direction& incident, const Direction& outwardNormal, double n1, double n2) {
    const Eigen::Vector3d& i = incident.vector();
    const Eigen::Vector3d& n = outwardNormal.vector();
    const double cosine = i.dot(n);
    if (cosine == 0.0) return {InterfaceOutcome::Tangent, Direction::invalid()};
    const Eigen::Vector3d c = (n1 / n2) * i.cross(n);  // seed eq. 4.2
    const double sine = c.norm();                      // t_perp, seed eq. 4.6
    if (sine > 1.0) return {InterfaceOutcome::TotalInternalReflection, Direction::invalid()};
    const double parallel = std::copysign(std::sqrt((1.0 - sine) * (1.0 + sine)), cosine);
    // |c| (n x c^) = n x c, which also holds at normal incidence where c^ is undefined.
    return {InterfaceOutcome::Refracted, Direction(n.cross(c) + parallel * n)};  // seed eq. 4.7
}

Direction reflect(const Direction& incident, const Direction& normal) {
    const Eigen::Vector3d& v = incident.vector();
    const Eigen::Vector3d& n = normal.vector();
    return Direction(v - 2.0 * v.dot(n) * n);
}

}  // namespace dropscope
