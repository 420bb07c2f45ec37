#include "transport/DropletDiffraction.hpp"

#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"

#include <cmath>

namespace dropscope {
namespace {

// Two unit vectors completing `d` to a right-handed orthonormal basis.
std::pair<Eigen::Vector3d, Eigen::Vector3d> transverseBasis(const Direction& d) {
    const Eigen::Vector3d helper = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d e1 = d.vector().cross(helper).normalized();
    return {e1, d.vector().cross(e1)};
}

}  // namespace

std::string_view diffractionModelName(DiffractionModel model) {
    return model == DiffractionModel::Fraunhofer ? "fraunhofer" : "none";
}

std::optional<ProjectedEllipse> projectedOutline(const Shape& shape, const Direction& direction) {
    const auto [t1, t2] = transverseBasis(direction);
    if (shape.kind() == ShapeKind::Sphere) {
        const double r = static_cast<const Sphere&>(shape).radius();
        return ProjectedEllipse{r, r, t1, t2};
    }
    if (shape.kind() != ShapeKind::Ellipsoid) return std::nullopt;
    // The ellipsoid x.M x <= 1 projects along d onto the ellipse y.C^-1 y <= 1 of the plane, where C is
    // M^-1 restricted to the plane (the support function of the body is sqrt(n.M^-1 n)): its eigenvalues are
    // the squared semi-axes.
    const Eigen::Matrix3d& inverse = static_cast<const Ellipsoid&>(shape).inverseMatrix();
    const double c11 = t1.dot(inverse * t1);
    const double c22 = t2.dot(inverse * t2);
    const double c12 = t1.dot(inverse * t2);
    const double mean = 0.5 * (c11 + c22);
    const double radius = std::hypot(0.5 * (c11 - c22), c12);
    const double major = mean + radius;
    const double minor = std::max(mean - radius, 0.0);
    // The major axis's eigenvector, from whichever row of C - major I is larger (a disk: any axis).
    Eigen::Vector2d axis = std::abs(c11 - major) + std::abs(c12) >= std::abs(c22 - major) + std::abs(c12)
                               ? Eigen::Vector2d(c12, major - c11)
                               : Eigen::Vector2d(major - c22, c12);
    if (axis.norm() == 0.0) axis = Eigen::Vector2d::UnitX();
    axis.normalize();
    const Eigen::Vector3d e1 = axis.x() * t1 + axis.y() * t2;
    return ProjectedEllipse{std::sqrt(major), std::sqrt(minor), e1, direction.vector().cross(e1)};
}

}  // namespace dropscope
