#include "scene/TransformReader.hpp"

#include <array>
#include <numbers>
#include <string_view>

namespace dropscope {

namespace {

Eigen::Vector3d readScale(const JsonReader& json) {
    if (json.isNumber()) return Eigen::Vector3d::Constant(json.number());
    return json.vector3();
}

AffineTransform readRotation(const JsonReader& json) {
    json.expectKeys({"axis", "angle_deg"});
    const Eigen::Vector3d axis = json.member("axis").direction().vector();
    const double angleDegrees = json.member("angle_deg").number();
    return AffineTransform::rotation(axis, angleDegrees * std::numbers::pi / 180.0);
}

AffineTransform readShear(const JsonReader& json) {
    static constexpr std::array<std::string_view, 6> kKeys{"xy", "xz", "yx", "yz", "zx", "zy"};
    json.expectKeys({"xy", "xz", "yx", "yz", "zx", "zy"});
    Eigen::Matrix<double, 6, 1> factors = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t i = 0; i < kKeys.size(); ++i) {
        if (const auto factor = json.optionalMember(kKeys[i])) factors[static_cast<Eigen::Index>(i)] = factor->number();
    }
    return AffineTransform::shear(factors);
}

AffineTransform readReflection(const JsonReader& json) {
    json.expectKeys({"normal"});
    return AffineTransform::reflection(json.member("normal").direction().vector());
}

}  // namespace

AffineTransform readTransform(const JsonReader& json) {
    json.expectKeys({"scale", "rotation", "shear", "reflection", "matrix", "translation"});
    AffineTransform result;
    // Each step is checked where it is read, so a singular scale or matrix names its own key.
    const auto apply = [&](std::string_view key, auto read) {
        if (const auto step = json.optionalMember(key)) {
            const AffineTransform next = step->construct([&] { return read(*step); });
            result = step->construct([&] { return result.then(next); });
        }
    };
    apply("scale", [](const JsonReader& j) { return AffineTransform::scaling(readScale(j)); });
    apply("rotation", readRotation);
    apply("shear", readShear);
    apply("reflection", readReflection);
    apply("matrix", [](const JsonReader& j) { return AffineTransform(j.matrix3(), Eigen::Vector3d::Zero()); });
    apply("translation", [](const JsonReader& j) { return AffineTransform::translation(j.vector3()); });
    return result;
}

}  // namespace dropscope
