#include "scene/ShapeSpec.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument(message);
}

std::unique_ptr<Shape> makeSphere(const ShapeSpec& spec) {
    require(spec.center.allFinite(), "center must be finite");
    require(std::isfinite(spec.radius), "radius must be finite");
    require(spec.radius > 0.0, "radius must be > 0");
    return std::make_unique<Sphere>(spec.center, spec.radius);
}

std::unique_ptr<Shape> makeEllipsoid(const ShapeSpec& spec) {
    require(spec.center.allFinite(), "center must be finite");
    require(spec.semiAxes.allFinite(), "semi-axes must be finite");
    require((spec.semiAxes.array() > 0.0).all(), "semi-axes must be > 0");
    require(std::isfinite(spec.rotationAngleDeg), "rotation angle must be finite");
    const Direction axis(spec.rotationAxis);
    require(static_cast<bool>(axis), "rotation axis must be a finite, non-zero vector");
    const Eigen::Matrix3d rotation = rotationAboutAxis(axis, spec.rotationAngleDeg / kDegreesPerRadian);
    return std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(spec.center, spec.semiAxes, rotation));
}

std::unique_ptr<Shape> makeBox(const ShapeSpec& spec) {
    require(spec.boxMin.allFinite() && spec.boxMax.allFinite(), "box corners must be finite");
    for (Eigen::Index axis = 0; axis < 3; ++axis) {
        require(spec.boxMin[axis] < spec.boxMax[axis],
                "box max must be > min on every axis (" + std::string(1, "xyz"[axis]) + ": max " +
                    jsonpath::number(spec.boxMax[axis]) + " <= min " + jsonpath::number(spec.boxMin[axis]) + ")");
    }
    return std::make_unique<Box>(spec.boxMin, spec.boxMax);
}

std::unique_ptr<Shape> makeGeneral(const ShapeSpec& spec) {
    require(spec.general != nullptr && spec.general->kind() == spec.kind, "no parametric or implicit shape given");
    require(spec.center.allFinite(), "center must be finite");
    return spec.general->withTransform(AffineTransform(spec.general->transform().matrix(), spec.center));
}

}  // namespace

std::unique_ptr<Shape> makeShape(const ShapeSpec& spec) {
    std::unique_ptr<Shape> shape;
    switch (spec.kind) {
    case ShapeKind::Sphere: shape = makeSphere(spec); break;
    case ShapeKind::Ellipsoid: shape = makeEllipsoid(spec); break;
    case ShapeKind::Box: shape = makeBox(spec); break;
    case ShapeKind::Parametric:
    case ShapeKind::Implicit: shape = makeGeneral(spec); break;
    }
    require(shape != nullptr, "unknown shape kind");
    shape->setMediumId(spec.medium);
    return shape;
}

ShapeSpec describeShape(const Shape& shape) {
    ShapeSpec spec;
    spec.kind = shape.kind();
    spec.medium = shape.mediumId();
    switch (shape.kind()) {
    case ShapeKind::Sphere: {
        const auto& sphere = static_cast<const Sphere&>(shape);
        spec.center = sphere.center();
        spec.radius = sphere.radius();
        break;
    }
    case ShapeKind::Ellipsoid: {
        const auto& ellipsoid = static_cast<const Ellipsoid&>(shape);
        const EllipsoidFrame frame = ellipsoidFrame(ellipsoid);
        const AxisAngle turn = axisAngleOf(frame.rotation);
        spec.center = ellipsoid.center();
        spec.semiAxes = frame.semiAxes;
        spec.rotationAxis = turn.axis;
        spec.rotationAngleDeg = turn.angleDeg;
        break;
    }
    case ShapeKind::Box: {
        const auto& box = static_cast<const Box&>(shape);
        spec.center = box.center();
        spec.boxMin = box.lower();
        spec.boxMax = box.upper();
        break;
    }
    case ShapeKind::Parametric:
    case ShapeKind::Implicit: {
        const auto& general = static_cast<const GeneralShape&>(shape);
        spec.center = general.transform().translation();
        spec.general = std::shared_ptr<const GeneralShape>(general.withTransform(general.transform()));
        break;
    }
    }
    return spec;
}

ShapeSpec withCenter(ShapeSpec spec, const Point& center) {
    if (spec.kind == ShapeKind::Box) {
        const Eigen::Vector3d half = 0.5 * (spec.boxMax - spec.boxMin);
        spec.boxMin = center - half;
        spec.boxMax = center + half;
    }
    spec.center = center;
    return spec;
}

AxisAngle axisAngleOf(const Eigen::Matrix3d& rotation) {
    // Quaternion by Shepperd's branch on the largest diagonal term, then angle = 2 atan2(|v|, |w|):
    // no acos of a trace, so small angles and angles near 180 degrees keep their digits.
    const Eigen::AngleAxisd turn{Eigen::Quaterniond(rotation)};
    if (turn.angle() == 0.0) return {};
    // Adding +0 turns a -0 component into 0, which reads better in a file and is the same axis.
    return {turn.axis() + Eigen::Vector3d::Zero(), turn.angle() * kDegreesPerRadian};
}

EllipsoidFrame ellipsoidFrame(const Ellipsoid& ellipsoid) {
    const Eigen::Matrix3d& axes = ellipsoid.axes();
    EllipsoidFrame best{ellipsoid.semiAxes(), axes};
    double bestTrace = -std::numeric_limits<double>::infinity();
    std::array<int, 3> order{0, 1, 2};
    do {
        // Column i is semi-axis order[i]'s direction, signed to point along +e_i where it can.
        Eigen::Matrix3d rotation;
        Eigen::Vector3d semiAxes;
        for (int i = 0; i < 3; ++i) {
            const auto column = static_cast<Eigen::Index>(order[static_cast<std::size_t>(i)]);
            rotation.col(i) = axes.col(column);
            if (rotation(i, i) < 0.0) rotation.col(i) = -rotation.col(i);
            semiAxes[i] = ellipsoid.semiAxes()[column];
        }
        // A reflection: flip the column that costs the least trace.
        if (rotation.determinant() < 0.0) {
            Eigen::Index weakest = 0;
            rotation.diagonal().cwiseAbs().minCoeff(&weakest);
            rotation.col(weakest) = -rotation.col(weakest);
        }
        if (rotation.trace() > bestTrace) {
            bestTrace = rotation.trace();
            best = {semiAxes, rotation};
        }
    } while (std::next_permutation(order.begin(), order.end()));
    return best;
}

}  // namespace dropscope
