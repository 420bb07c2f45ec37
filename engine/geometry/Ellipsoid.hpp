#pragma once

#include "geometry/Shape.hpp"

#include <Eigen/Core>

namespace dropscope {

// Ellipsoid (r - r0) . M (r - r0) = 1 with M symmetric positive definite (seed 1.3).
class Ellipsoid : public Shape {
public:
    // M = R diag(1/a^2, 1/b^2, 1/c^2) R^T: the columns of `rotation` are the directions of the
    // semi-axes. Throws std::invalid_argument on non-positive semi-axes or a non-orthonormal rotation.
    static Ellipsoid fromSemiAxes(const Point& center, const Eigen::Vector3d& semiAxes,
                                  const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity());
    // Throws std::invalid_argument when M is not symmetric positive definite.
    static Ellipsoid fromMatrix(const Point& center, const Eigen::Matrix3d& m);

    const Point& center() const { return center_; }
    const Eigen::Matrix3d& matrix() const { return m_; }
    const Eigen::Matrix3d& inverseMatrix() const { return mInverse_; }
    // Semi-axis lengths, longest first, and the unit axis directions as matching columns.
    const Eigen::Vector3d& semiAxes() const { return semiAxes_; }
    const Eigen::Matrix3d& axes() const { return axes_; }

    ShapeKind kind() const override { return ShapeKind::Ellipsoid; }
    std::string_view typeName() const override { return "ellipsoid"; }

    double xMin() const override { return center_.x() - halfExtent_.x(); }
    double xMax() const override { return center_.x() + halfExtent_.x(); }
    double yMin() const override { return center_.y() - halfExtent_.y(); }
    double yMax() const override { return center_.y() + halfExtent_.y(); }
    double zMin() const override { return center_.z() - halfExtent_.z(); }
    double zMax() const override { return center_.z() + halfExtent_.z(); }

    double surfaceArea() const override { return surfaceArea_; }
    double volume() const override;
    PointLocation locatePoint(const Point& p) const override;
    double distanceToSurface(const Point& p, const Direction& d) const override;
    Direction normal(const Point& p) const override;
    bool mayMeetBox(const Eigen::AlignedBox3d& box) const override;
    bool sameFormAs(const Shape& other) const override;
    void print(std::ostream& os) const override;
    std::unique_ptr<Shape> clone() const override { return std::make_unique<Ellipsoid>(*this); }
    double surfaceBand() const override { return bandNormalised_ * semiAxes_.minCoeff(); }

    // (r - r0) . M (r - r0): < 1 inside, 1 on the surface.
    double quadraticForm(const Point& p) const;
    // Half-width of the surface band in the unit-sphere frame, i.e. on sqrt(quadraticForm).
    double normalisedBand() const { return bandNormalised_; }

private:
    Ellipsoid(const Point& center, const Eigen::Matrix3d& m);

    Point center_;
    Eigen::Matrix3d m_;
    Eigen::Matrix3d mInverse_;
    Eigen::Vector3d semiAxes_;
    Eigen::Matrix3d axes_;
    Eigen::Matrix3d toUnitSphere_;  // T with |T (r - r0)| = 1 on the surface (M = T^T T)
    Eigen::Vector3d halfExtent_;
    double surfaceArea_;
    double bandNormalised_;
};

// Exact surface area of an ellipsoid with the given semi-axes (any order), through Carlson's
// symmetric integral R_G; exact for spheres and spheroids too.
double ellipsoidSurfaceArea(const Eigen::Vector3d& semiAxes);

}  // namespace dropscope
