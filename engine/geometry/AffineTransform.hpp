#pragma once

#include "geometry/Vector.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dropscope {

// What the SVD M = U S V^T (seed 000 section A.2) says M is made of.
struct TransformClass {
    Eigen::Vector3d singularValues;  // descending
    double determinant = 1.0;
    // Only rotations, reflections and one uniform scaling K (all singular values equal within
    // tolerance::kMatrixRelative): areas scale by K^2, volumes by K^3, shapes keep their form.
    bool isSimilarity = true;
    double uniformScale = 1.0;  // K when isSimilarity (the mean singular value), else 0
    bool reflects = false;      // det M < 0
};

// r -> M r + r0 with M invertible: how a parametric or implicit shape is placed relative to its
// shared base (seed 000 Appendix A). A parametric base r(u, v) becomes M r(u, v) + r0; an implicit
// base f(r) becomes f(M^-1 (r - r0)).
class AffineTransform {
public:
    AffineTransform() = default;  // the identity
    // Throws std::invalid_argument when M or r0 is not finite, or M is singular: its smallest singular
    // value below tolerance::kMatrixRelative times its largest.
    AffineTransform(const Eigen::Matrix3d& m, const Eigen::Vector3d& translation);

    // Builders (seed A.1-A.6). Each throws std::invalid_argument on input that gives no valid M.
    static AffineTransform rotation(const Eigen::Vector3d& axis, double angleRadians);  // A.1, A.2
    static AffineTransform reflection(const Eigen::Vector3d& planeNormal);              // A.3
    static AffineTransform scaling(const Eigen::Vector3d& factors);                     // A.4
    static AffineTransform uniformScaling(double factor);                               // A.5
    // A.6: the 3x3 with ones on the diagonal and the six off-diagonal factors
    // (xy, xz, yx, yz, zx, zy) row by row.
    static AffineTransform shear(const Eigen::Matrix<double, 6, 1>& offDiagonal);
    static AffineTransform translation(const Eigen::Vector3d& offset);

    // `next` applied after *this: r -> next(this(r)).
    AffineTransform then(const AffineTransform& next) const;

    const Eigen::Matrix3d& matrix() const { return m_; }
    const Eigen::Matrix3d& inverseMatrix() const { return mInverse_; }
    const Eigen::Vector3d& translation() const { return r0_; }
    const TransformClass& classification() const { return class_; }
    double determinant() const { return class_.determinant; }
    bool isIdentity() const;

    Point apply(const Point& r) const { return m_ * r + r0_; }
    Point applyInverse(const Point& r) const { return mInverse_ * (r - r0_); }
    Eigen::Vector3d applyToVector(const Eigen::Vector3d& v) const { return m_ * v; }
    Eigen::Vector3d applyInverseToVector(const Eigen::Vector3d& v) const { return mInverse_ * v; }
    // A normal (covector) of the base mapped to the placed shape: M^-T n, normalised. Outward stays
    // outward even when M reflects, because the inside maps to the inside.
    Direction applyToNormal(const Eigen::Vector3d& baseNormal) const {
        return Direction(mInverse_.transpose() * baseNormal);
    }
    // The axis-aligned box around the image of `box` (its 8 corners mapped).
    Eigen::AlignedBox3d applyToBox(const Eigen::AlignedBox3d& box) const;

private:
    Eigen::Matrix3d m_ = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d mInverse_ = Eigen::Matrix3d::Identity();
    Eigen::Vector3d r0_ = Eigen::Vector3d::Zero();
    TransformClass class_{Eigen::Vector3d::Ones(), 1.0, true, 1.0, false};
};

}  // namespace dropscope
