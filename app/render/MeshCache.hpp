#pragma once

#include "geometry/GeneralShape.hpp"
#include "render/DrawData.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace dropscope::render {

// The drawn geometry of `shape`: GeneralShape::mesh() in float, relative to the translation r0, with
// drawnNormals.
MeshGeometry meshGeometry(const GeneralShape& shape);

// The mesh's normals as drawn: each one more than 60 degrees off the triangles around it, or not finite
// (a broken normal, e.g. at a pole where a Bezier patch edge collapses to a point), replaced by the
// area-weighted mean normal of those triangles; the others as they are.
std::vector<Eigen::Vector3d> drawnNormals(const SurfaceMesh& mesh);

// The geometries of the GeneralShapes of a scene, kept between uploads. The GUI uploads the whole scene
// whenever something changes (a selection, every step of a drag), and placing every mesh each time would
// cost all their vertices. Two shapes get one geometry when they have the same kind, preset, preset
// parameters and matrix M: their bases are then the same, so their meshes differ only by r0, which the
// geometry leaves out. Moving a shape therefore finds its geometry here.
class MeshCache {
public:
    std::shared_ptr<const MeshGeometry> geometry(const GeneralShape& shape);
    // Forgets the geometries not asked for since the last call (shapes deleted or reshaped).
    void dropUnused();
    std::size_t size() const { return entries_.size(); }
    std::size_t made() const { return made_; }  // geometries made so far

private:
    struct Entry {
        ShapeKind kind;
        std::string preset;
        std::vector<PresetParameter> parameters;
        Eigen::Matrix3d matrix;
        std::shared_ptr<const MeshGeometry> geometry;
        bool used = true;
    };
    std::unordered_multimap<std::size_t, Entry> entries_;
    std::size_t made_ = 0;
};

}  // namespace dropscope::render
