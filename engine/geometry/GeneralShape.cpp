#include "geometry/GeneralShape.hpp"

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

std::string shapeTypeLabel(const Shape& shape) {
    std::string label(shape.typeName());
    if (const GeneralShape* general = asGeneralShape(shape)) label.append(" ").append(general->presetName());
    return label;
}

Point GeneralShape::surfacePoint() const { return transform_.apply(baseMesh().vertices.front()); }

}  // namespace dropscope
