#include "gui/DetectorDefaults.hpp"

#include "render/SceneLayers.hpp"

#include <algorithm>

namespace dropscope::gui {

namespace {

constexpr double kScreenDistance = 1.5;  // bounding radii beyond the shapes' centre
constexpr double kScreenSide = 3.0;      // bounding radii
constexpr int kDefaultPixels = 64;
constexpr double kDefaultFovDeg = 120.0;

// The way the first source's light goes.
Eigen::Vector3d lightDirection(const SceneDocument& document, const Point& centre) {
    if (document.sources().empty()) return Eigen::Vector3d::UnitZ();
    const Source& source = document.sources().front();
    if (source.type != SourceType::PointSource && source.direction) return source.direction.vector();
    const Direction towards(centre - source.origin);
    return towards ? towards.vector() : Eigen::Vector3d::UnitZ();
}

// The world axis least along `direction`: an up the detector's checks accept.
Eigen::Vector3d upAcross(const Eigen::Vector3d& direction) {
    const Eigen::Vector3d a = direction.cwiseAbs();
    if (a.y() <= a.x() && a.y() <= a.z()) return Eigen::Vector3d::UnitY();
    return a.z() <= a.x() ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
}

}  // namespace

std::string unusedDetectorName(const SceneDocument& document, const std::string& base) {
    const auto used = [&](const std::string& name) {
        return std::any_of(document.detectors().begin(), document.detectors().end(),
                           [&](const Detector& d) { return d.name == name; });
    };
    std::string name = base;
    for (int k = 2; used(name); ++k) name = base + "-" + std::to_string(k);
    return name;
}

Detector defaultDetector(const SceneDocument& document, DetectorType type) {
    const Eigen::AlignedBox3d bounds = render::sceneBounds(document.octree().shapes());
    const Point centre = bounds.center();
    const double radius = 0.5 * bounds.diagonal().norm();
    const Eigen::Vector3d light = lightDirection(document, centre);
    Detector detector;
    detector.type = type;
    detector.up = upAcross(light);
    detector.pixels = {kDefaultPixels, kDefaultPixels};
    switch (type) {
    case DetectorType::Plane:
        detector.name = unusedDetectorName(document, "screen");
        detector.center = centre + kScreenDistance * radius * light;
        detector.normal = Direction(-light);
        detector.size = {kScreenSide * radius, kScreenSide * radius};
        break;
    case DetectorType::FarField:
        detector.name = unusedDetectorName(document, "sky");
        detector.look = Direction(light);
        detector.fovDeg = kDefaultFovDeg;
        break;
    case DetectorType::ShapeAbsorption: detector.name = unusedDetectorName(document, "absorbed"); break;
    }
    return detector;
}

}  // namespace dropscope::gui
