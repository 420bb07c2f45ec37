#include "geometry/Rotation.hpp"

#include <cmath>

namespace dropscope {

Eigen::Matrix3d rotationAboutAxis(const Direction& axis, double angleRadians) {
    Eigen::Matrix3d omega;  // seed eq. A.2
    omega << 0.0, -axis.z(), axis.y(), axis.z(), 0.0, -axis.x(), -axis.y(), axis.x(), 0.0;
    return Eigen::Matrix3d::Identity() + omega * std::sin(angleRadians) +
           omega * omega * (1.0 - std::cos(angleRadians));  // seed eq. A.1
}

}  // namespace dropscope
