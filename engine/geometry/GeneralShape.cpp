#include "geometry/GeneralShape.hpp"

#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace dropscope {

SurfaceMesh GeneralShape::mesh() const {
    const SurfaceMesh& base = baseMesh();
    SurfaceMesh placed;
    placed.vertices.reserve(base.vertices.size());
    placed.normals.reserve(base.normals.size());
    for (const Point& v : base.vertices) placed.vertices.push_back(transform_.apply(v));
    for (const Eigen::Vector3d& n : base.normals) placed.normals.push_back(transform_.applyToNormal(n).vector());
    placed.triangles = base.triangles;
    // A reflection turns the winding inside out; swapping two corners keeps it counter-clockwise outside.
    if (transform_.classification().reflects) {
        for (auto& triangle : placed.triangles) std::swap(triangle[1], triangle[2]);
    }
    return placed;
}

std::vector<Eigen::AlignedBox3d> GeneralShape::surfaceCover() const {
    const std::vector<Eigen::AlignedBox3d>& base = baseSurfaceCover();
    std::vector<Eigen::AlignedBox3d> placed;
    placed.reserve(base.size());
    for (const Eigen::AlignedBox3d& box : base) placed.push_back(transform_.applyToBox(box));
    return placed;
}

namespace {

// More numbers than this in one parameter are summarised when printed.
constexpr std::size_t kPrintedValues = 12;

// The values of one preset parameter as nested brackets following its extents ("1", "[1, 2]", ...).
void printValues(std::ostream& os, const PresetParameter& parameter, std::size_t level, std::size_t& next) {
    if (level == parameter.extents.size()) {
        os << parameter.values[next++];
        return;
    }
    os << '[';
    for (std::size_t i = 0; i < parameter.extents[level]; ++i) {
        if (i > 0) os << ", ";
        printValues(os, parameter, level + 1, next);
    }
    os << ']';
}

}  // namespace

bool GeneralShape::mayMeetBox(const Eigen::AlignedBox3d& box) const {
    if (!bounds().intersects(box)) return false;
    if (anyCoverBox([&](const Eigen::AlignedBox3d& cell) { return cell.intersects(box); })) return true;
    // No surface in the box: it is wholly inside or wholly outside.
    return locatePoint(box.center()) != PointLocation::Outside;
}

bool GeneralShape::sameFormAs(const Shape& other) const {
    const auto* general = dynamic_cast<const GeneralShape*>(&other);
    return general && general->kind() == kind() && general->transform().matrix() == transform().matrix() &&
           general->presetName() == presetName() && general->presetParameters() == presetParameters();
}

void GeneralShape::print(std::ostream& os) const {
    os << typeName() << ' ' << presetName() << " {";
    const std::vector<PresetParameter> parameters = presetParameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        os << (i ? ", " : "") << parameters[i].key << ": ";
        if (parameters[i].values.size() > kPrintedValues) {
            os << '[' << parameters[i].values.size() << " numbers]";
            continue;
        }
        std::size_t next = 0;
        printValues(os, parameters[i], 0, next);
    }
    const Eigen::Matrix3d& m = transform_.matrix();
    os << "} M=[";
    for (int i = 0; i < 3; ++i) os << (i ? ", [" : "[") << m(i, 0) << ", " << m(i, 1) << ", " << m(i, 2) << ']';
    os << "] r0=";
    printPoint(os, transform_.translation());
}

std::string shapeTypeLabel(const Shape& shape) {
    std::string label(shape.typeName());
    if (const GeneralShape* general = asGeneralShape(shape)) label.append(" ").append(general->presetName());
    return label;
}

Point GeneralShape::surfacePoint() const {
    const SurfaceMesh& base = baseMesh();
    if (base.vertices.empty()) throw std::logic_error("surfacePoint of a shape without a mesh (see checkUsable)");
    return transform_.apply(base.vertices.front());
}

void GeneralShape::checkUsable() const {
    const Eigen::AlignedBox3d box = bounds();
    if (!box.min().allFinite() || !box.max().allFinite() || box.isEmpty()) {
        throw std::invalid_argument("its extent is not finite (parameters or transform beyond the double range)");
    }
    const double v = volume();
    const double s = surfaceArea();
    if (!std::isfinite(v) || !(v > 0.0) || !std::isfinite(s) || !(s > 0.0)) {
        throw std::invalid_argument("its volume or area is not a positive finite number (volume " + std::to_string(v) +
                                    ", area " + std::to_string(s) + ")");
    }
    if (baseMesh().vertices.empty() || baseMesh().triangles.empty()) {
        throw std::invalid_argument(
            "its surface is too fine for the tessellation (a droplet far smaller than the shape?)");
    }
}

}  // namespace dropscope
