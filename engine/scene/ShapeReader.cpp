#include "scene/ShapeReader.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Rotation.hpp"
#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"
#include "scene/MediaReader.hpp"
#include "scene/SceneLimits.hpp"

#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

std::unique_ptr<Shape> readSphere(const JsonReader& json) {
    json.expectKeys({"type", "center", "radius", "medium", "name"});
    const Point center = json.member("center").vector3();
    const double radius = json.member("radius").positive();
    return json.construct([&] { return std::make_unique<Sphere>(center, radius); });
}

std::unique_ptr<Shape> readBox(const JsonReader& json) {
    json.expectKeys({"type", "min", "max", "medium", "name"});
    const Eigen::AlignedBox3d corners = readCorners(json);
    return json.construct([&] { return std::make_unique<Box>(corners.min(), corners.max()); });
}

// {"axis": [x, y, z], "angle_deg": a}: a right-handed rotation of a degrees about axis.
Eigen::Matrix3d readRotation(const JsonReader& json) {
    json.expectKeys({"axis", "angle_deg"});
    const Direction axis = json.member("axis").direction();
    const double angleDegrees = json.member("angle_deg").number();
    return rotationAboutAxis(axis, angleDegrees * std::numbers::pi / 180.0);
}

std::unique_ptr<Shape> readEllipsoid(const JsonReader& json) {
    json.expectKeys({"type", "center", "semi_axes", "rotation", "matrix", "medium", "name"});
    const Point center = json.member("center").vector3();
    const auto semiAxesJson = json.optionalMember("semi_axes");
    const auto matrixJson = json.optionalMember("matrix");
    const auto rotationJson = json.optionalMember("rotation");
    if (semiAxesJson && matrixJson) json.fail("give either \"semi_axes\" or \"matrix\", not both");
    if (matrixJson) {
        if (rotationJson) rotationJson->fail("applies only with \"semi_axes\" (a \"matrix\" is already rotated)");
        const Eigen::Matrix3d m = matrixJson->matrix3();
        return matrixJson->construct([&] { return std::make_unique<Ellipsoid>(Ellipsoid::fromMatrix(center, m)); });
    }
    if (!semiAxesJson) json.fail("missing required key \"semi_axes\" or \"matrix\"");
    const Eigen::Vector3d semiAxes = semiAxesJson->positiveVector3();
    const Eigen::Matrix3d rotation = rotationJson ? readRotation(*rotationJson) : Eigen::Matrix3d::Identity();
    return json.construct(
        [&] { return std::make_unique<Ellipsoid>(Ellipsoid::fromSemiAxes(center, semiAxes, rotation)); });
}

}  // namespace

Eigen::AlignedBox3d readCorners(const JsonReader& json) {
    const Point lower = json.member("min").vector3();
    const JsonReader upperJson = json.member("max");
    const Point upper = upperJson.vector3();
    for (const auto& [corner, key] : {std::pair{lower, "min"}, std::pair{upper, "max"}}) {
        if (!withinCoordinateLimit(corner)) json.member(key).fail(beyondCoordinateLimit());
    }
    for (Eigen::Index axis = 0; axis < 3; ++axis) {
        if (!(lower[axis] < upper[axis])) {
            upperJson.fail("must be > \"min\" on every axis (" + std::string(1, "xyz"[axis]) + ": max " +
                           jsonpath::number(upper[axis]) + " <= min " + jsonpath::number(lower[axis]) + ")");
        }
    }
    return {lower, upper};
}

NamedShape readShape(const JsonReader& json, const std::vector<Medium>& media, BaseCache& cache) {
    const JsonReader typeJson = json.member("type");
    const std::string type = typeJson.string();
    NamedShape result;
    if (type == "sphere") {
        result.shape = readSphere(json);
    } else if (type == "ellipsoid") {
        result.shape = readEllipsoid(json);
    } else if (type == "box") {
        result.shape = readBox(json);
    } else if (type == "parametric") {
        result.shape = readParametricShape(json, cache);
    } else if (type == "implicit") {
        result.shape = readImplicitShape(json, cache);
    } else {
        typeJson.fail("unknown shape type " + jsonpath::quoted(type) +
                      " (known: sphere, ellipsoid, box, parametric, implicit)");
    }
    result.shape->setMediumId(readMediumName(json.member("medium"), media));
    if (const auto name = json.optionalMember("name")) {
        result.name = name->string();
        if (result.name.empty()) name->fail("must not be empty (leave \"name\" out for an unnamed shape)");
    }
    return result;
}

}  // namespace dropscope
