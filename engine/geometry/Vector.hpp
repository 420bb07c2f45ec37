#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products of directions

#include <algorithm>
#include <cmath>
#include <ostream>

namespace dropscope {

using Point = Eigen::Vector3d;

// A direction in space: always unit length, or all-NaN when it was built from a zero or non-finite
// vector (seed 001 "Vector"). Like a pointer, an invalid one converts to false.
class UnitVector3d {
public:
    UnitVector3d() : v_(Eigen::Vector3d::Constant(std::nan(""))) {}
    explicit UnitVector3d(const Eigen::Vector3d& v) : v_(normalised(v)) {}
    UnitVector3d(double x, double y, double z) : UnitVector3d(Eigen::Vector3d(x, y, z)) {}

    static UnitVector3d invalid() { return UnitVector3d(); }
    // The direction whose vector() was `components`, taken as is (not normalised again, which could move a
    // last bit): for a direction copied through bytes, e.g. between the processes of one run.
    static UnitVector3d restored(const Eigen::Vector3d& components) { return fromUnit(components); }

    explicit operator bool() const { return !std::isnan(v_.x()); }

    const Eigen::Vector3d& vector() const { return v_; }
    operator const Eigen::Vector3d&() const { return v_; }  // NOLINT: a direction is a vector
    double x() const { return v_.x(); }
    double y() const { return v_.y(); }
    double z() const { return v_.z(); }
    double operator[](Eigen::Index i) const { return v_[i]; }
    double dot(const Eigen::Vector3d& other) const { return v_.dot(other); }

    UnitVector3d operator-() const { return fromUnit(-v_); }

private:
    static Eigen::Vector3d normalised(const Eigen::Vector3d& v) {
        // Scaling by the largest component first keeps 1e-300 or 1e300 components from under/overflowing.
        if (!v.allFinite()) return Eigen::Vector3d::Constant(std::nan(""));
        const double largest = v.cwiseAbs().maxCoeff();
        if (largest == 0.0) return Eigen::Vector3d::Constant(std::nan(""));
        const Eigen::Vector3d scaled = v / largest;
        return scaled / scaled.norm();
    }
    static UnitVector3d fromUnit(const Eigen::Vector3d& unit) {
        UnitVector3d d;
        d.v_ = unit;
        return d;
    }

    Eigen::Vector3d v_;
};

using Direction = UnitVector3d;

inline std::ostream& operator<<(std::ostream& os, const UnitVector3d& d) {
    return os << '(' << d.x() << ", " << d.y() << ", " << d.z() << ')';
}

// The largest absolute coordinate of a box's corners: how far its points reach from the origin on any axis,
// and so the scale of their rounding.
inline double largestCoordinate(const Eigen::AlignedBox3d& box) {
    return std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
}

// "(x, y, z)" — the one way points are printed by print() and the CLI.
inline std::ostream& printPoint(std::ostream& os, const Point& p) {
    return os << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
}

}  // namespace dropscope
