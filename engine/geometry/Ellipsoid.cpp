#include "geometry/Ellipsoid.hpp"

#include "geometry/Box.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/RayQuadric.hpp"
#include "geometry/Tolerance.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace dropscope {

namespace {

std::string describeMatrix(const Eigen::Matrix3d& m) {
    std::ostringstream os;
    os << '[';
    for (int i = 0; i < 3; ++i) {
        os << (i ? ", [" : "[") << m(i, 0) << ", " << m(i, 1) << ", " << m(i, 2) << ']';
    }
    os << ']';
    return os.str();
}

}  // namespace

Ellipsoid Ellipsoid::fromSemiAxes(const Point& center, const Eigen::Vector3d& semiAxes,
                                  const Eigen::Matrix3d& rotation) {
    if (!semiAxes.allFinite() || (semiAxes.array() <= 0.0).any())
        throw std::invalid_argument("ellipsoid semi-axes must be finite and > 0");
    const double deviation = (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(deviation <= tolerance::kMatrixRelative))
        throw std::invalid_argument("ellipsoid rotation is not orthonormal: " + describeMatrix(rotation));
    const Eigen::Vector3d inverseSquares = semiAxes.cwiseProduct(semiAxes).cwiseInverse();
    return Ellipsoid(center, rotation * inverseSquares.asDiagonal() * rotation.transpose());  // seed eq. 1.25
}

Ellipsoid Ellipsoid::fromMatrix(const Point& center, const Eigen::Matrix3d& m) {
    if (!m.allFinite()) throw std::invalid_argument("ellipsoid matrix must be finite");
    const double scale = m.cwiseAbs().maxCoeff();
    if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= tolerance::kMatrixRelative * scale))
        throw std::invalid_argument("ellipsoid matrix is not symmetric: " + describeMatrix(m));
    return Ellipsoid(center, 0.5 * (m + m.transpose()));
}

Ellipsoid::Ellipsoid(const Point& center, const Eigen::Matrix3d& m) : center_(center), m_(m) {
    if (!center.allFinite()) throw std::invalid_argument("ellipsoid centre must be finite");
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m);  // M = E Lambda E^T, seed eq. 1.25
    const Eigen::Vector3d lambda = eigen.eigenvalues();             // ascending: longest axis first
    if (eigen.info() != Eigen::Success || !(lambda.minCoeff() > 0.0))
        throw std::invalid_argument("ellipsoid matrix is not positive definite: " + describeMatrix(m));
    if (lambda.maxCoeff() > lambda.minCoeff() * tolerance::kMaxSemiAxisRatio * tolerance::kMaxSemiAxisRatio)
        throw std::invalid_argument("ellipsoid is too elongated: semi-axis ratio above 1e6");

    axes_ = eigen.eigenvectors();
    semiAxes_ = lambda.cwiseSqrt().cwiseInverse();
    mInverse_ = axes_ * semiAxes_.cwiseProduct(semiAxes_).asDiagonal() * axes_.transpose();  // seed eq. 1.26
    toUnitSphere_ = lambda.cwiseSqrt().asDiagonal() * axes_.transpose();
    // seed eqs. 1.27-1.29: half-extent along axis i is sqrt(sum_j s_j^2 E_ij^2)
    halfExtent_ = (axes_.cwiseProduct(axes_) * semiAxes_.cwiseProduct(semiAxes_)).cwiseSqrt();
    surfaceArea_ = ellipsoidSurfaceArea(semiAxes_);
    bandNormalised_ = tolerance::kSurfaceRelative +
                      tolerance::kCoordinateRelative * center.cwiseAbs().maxCoeff() / semiAxes_.minCoeff();
}

double Ellipsoid::volume() const { return 4.0 / 3.0 * std::numbers::pi * semiAxes_.prod(); }  // seed 1.3.3

double Ellipsoid::quadraticForm(const Point& p) const { return (toUnitSphere_ * (p - center_)).squaredNorm(); }

PointLocation Ellipsoid::locatePoint(const Point& p) const {
    // sqrt of seed eq. 1.13's left side: 1 on the surface, and changes at a rate ~1/semi-axis.
    const double radius = (toUnitSphere_ * (p - center_)).norm();
    if (std::isnan(radius)) return PointLocation::Outside;
    if (std::abs(radius - 1.0) <= bandNormalised_) return PointLocation::OnSurface;
    return radius < 1.0 ? PointLocation::Inside : PointLocation::Outside;
}

double Ellipsoid::distanceToSurface(const Point& p, const Direction& d) const {
    if (!d || !p.allFinite()) return std::nan("");
    // seed eqs. 1.58-1.61 in the unit-sphere frame y = T (r - r0), where M = T^T T.
    const Eigen::Vector3d y = toUnitSphere_ * (p - center_);
    const Eigen::Vector3d dy = toUnitSphere_ * d.vector();
    const double a = dy.squaredNorm();
    const double b = y.dot(dy);
    const double c = y.squaredNorm() - 1.0;
    // B^2 - AC = A (1 - |y - (B/A) dy|^2): squared half-chord in the unit frame, cancellation-free.
    const double perpendicular = (y - (b / a) * dy).norm();
    const double discriminant = a * (1.0 - perpendicular) * (1.0 + perpendicular);
    return quadricDistance({a, b, c, discriminant}, locatePoint(p), surfaceBand());
}

Direction Ellipsoid::normal(const Point& p) const {
    if (!surfaceContains(p)) return Direction::invalid();
    return Direction(m_ * (p - center_));  // seed eq. 1.62
}

bool Ellipsoid::mayMeetBox(const Eigen::AlignedBox3d& box) const {
    return bounds().intersects(box) && minimumQuadraticFormOverBox(center_, matrix(), Box(box.min(), box.max())) <= 1.0;
}

bool Ellipsoid::sameFormAs(const Shape& other) const {
    const auto* ellipsoid = dynamic_cast<const Ellipsoid*>(&other);
    return ellipsoid && ellipsoid->matrix() == matrix();
}

void Ellipsoid::print(std::ostream& os) const {
    os << "Ellipsoid(center=";
    printPoint(os, center_) << ", semi_axes=";
    printPoint(os, semiAxes_) << ", matrix=" << describeMatrix(m_) << ')';
}

}  // namespace dropscope
