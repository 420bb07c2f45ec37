#include "geometry/AffineTransform.hpp"

#include "geometry/Rotation.hpp"
#include "geometry/Tolerance.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace dropscope {

namespace {

// Seed 000 section A.2: the singular values say what M is made of. Rotations and reflections have all singular
// values 1; a uniform scaling K multiplies them all by K; anything else spreads them apart.
TransformClass classify(const Eigen::Matrix3d& m) {
    TransformClass result;
    result.singularValues = m.jacobiSvd().singularValues();
    result.determinant = m.determinant();
    result.reflects = result.determinant < 0.0;
    const double largest = result.singularValues[0];
    const double smallest = result.singularValues[2];
    result.isSimilarity = largest - smallest <= tolerance::kMatrixRelative * largest;
    result.uniformScale = result.isSimilarity ? result.singularValues.mean() : 0.0;
    return result;
}

}  // namespace

AffineTransform::AffineTransform(const Eigen::Matrix3d& m, const Eigen::Vector3d& translation)
    : m_(m), r0_(translation) {
    if (!m.allFinite()) throw std::invalid_argument("transformation matrix must be finite");
    if (!translation.allFinite()) throw std::invalid_argument("translation must be finite");
    class_ = classify(m);
    const Eigen::Vector3d& sigma = class_.singularValues;
    if (!(sigma[2] > tolerance::kMatrixRelative * sigma[0])) {
        std::ostringstream message;
        message << std::setprecision(3) << "transformation matrix is singular or too ill-conditioned (singular values "
                << sigma[0] << ", " << sigma[1] << ", " << sigma[2] << "; the smallest must exceed "
                << tolerance::kMatrixRelative << " times the largest)";
        throw std::invalid_argument(message.str());
    }
    mInverse_ = m.inverse();
}

AffineTransform AffineTransform::rotation(const Eigen::Vector3d& axis, double angleRadians) {
    const Direction unit(axis);
    if (!unit) throw std::invalid_argument("rotation axis must be finite and non-zero");
    if (!std::isfinite(angleRadians)) throw std::invalid_argument("rotation angle must be finite");
    return {rotationAboutAxis(unit, angleRadians), Eigen::Vector3d::Zero()};
}

AffineTransform AffineTransform::reflection(const Eigen::Vector3d& planeNormal) {
    const Direction n(planeNormal);
    if (!n) throw std::invalid_argument("reflection normal must be finite and non-zero");
    return {Eigen::Matrix3d::Identity() - 2.0 * n.vector() * n.vector().transpose(), Eigen::Vector3d::Zero()};  // A.3
}

AffineTransform AffineTransform::scaling(const Eigen::Vector3d& factors) {
    if (!factors.allFinite() || (factors.array() == 0.0).any()) {
        throw std::invalid_argument("scale factors must be finite and non-zero");
    }
    return {factors.asDiagonal().toDenseMatrix(), Eigen::Vector3d::Zero()};  // A.4
}

AffineTransform AffineTransform::uniformScaling(double factor) {
    return scaling(Eigen::Vector3d::Constant(factor));  // A.5
}

AffineTransform AffineTransform::shear(const Eigen::Matrix<double, 6, 1>& offDiagonal) {
    Eigen::Matrix3d m;  // A.6
    m << 1.0, offDiagonal[0], offDiagonal[1], offDiagonal[2], 1.0, offDiagonal[3], offDiagonal[4], offDiagonal[5], 1.0;
    return {m, Eigen::Vector3d::Zero()};
}

AffineTransform AffineTransform::translation(const Eigen::Vector3d& offset) {
    return {Eigen::Matrix3d::Identity(), offset};
}

AffineTransform AffineTransform::then(const AffineTransform& next) const {
    return {next.m_ * m_, next.m_ * r0_ + next.r0_};
}

bool AffineTransform::isIdentity() const { return m_ == Eigen::Matrix3d::Identity() && r0_ == Eigen::Vector3d::Zero(); }

Eigen::AlignedBox3d AffineTransform::applyToBox(const Eigen::AlignedBox3d& box) const {
    // The image's extent along each axis: centre mapped, half-widths through |M|.
    const Eigen::Vector3d center = apply(box.center());
    const Eigen::Vector3d half = m_.cwiseAbs() * (0.5 * box.sizes());
    return {center - half, center + half};
}

}  // namespace dropscope
