#include "render/MeshCache.hpp"

#include <functional>
#include <string_view>

namespace dropscope::render {

namespace {

std::array<float, 3> toFloat(const Eigen::Vector3d& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

// A vertex normal further than this (its cosine) from the mean normal of the triangles around it is not
// the surface's: an outward normal of a surface point lies within a few degrees of its neighbouring
// triangles on any usable tessellation, even at a rounded edge (about 45 degrees from each face there),
// while a broken one (e.g. at a pole where a patch edge collapses to a point, whose tangents vanish)
// lies anywhere, often across the surface, which draws as dark spikes. 60 degrees: far from both.
constexpr double kNormalAgreement = 0.5;

void combine(std::size_t& seed, std::size_t value) {
    seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

std::size_t keyHash(const GeneralShape& shape, std::string_view preset,
                    const std::vector<PresetParameter>& parameters) {
    std::size_t seed = static_cast<std::size_t>(shape.kind());
    combine(seed, std::hash<std::string_view>{}(preset));
    const std::hash<double> hashDouble;
    for (const PresetParameter& parameter : parameters) {
        combine(seed, std::hash<std::string>{}(parameter.key));
        for (const double value : parameter.values) combine(seed, hashDouble(value));
    }
    const Eigen::Matrix3d& m = shape.transform().matrix();
    for (Eigen::Index k = 0; k < m.size(); ++k) combine(seed, hashDouble(m(k)));
    return seed;
}

}  // namespace

std::vector<Eigen::Vector3d> drawnNormals(const SurfaceMesh& mesh) {
    std::vector<Eigen::Vector3d> around(mesh.vertices.size(), Eigen::Vector3d::Zero());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d n =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (const std::uint32_t k : t) around[k] += n;
    }
    std::vector<Eigen::Vector3d> normals = mesh.normals;
    for (std::size_t k = 0; k < normals.size(); ++k) {
        const double length = around[k].norm();
        if (!(length > 0.0)) continue;
        const Eigen::Vector3d mean = around[k] / length;
        if (!(normals[k].allFinite() && normals[k].dot(mean) >= kNormalAgreement)) normals[k] = mean;
    }
    return normals;
}

MeshGeometry meshGeometry(const GeneralShape& shape) {
    const SurfaceMesh mesh = shape.mesh();
    const std::vector<Eigen::Vector3d> normals = drawnNormals(mesh);
    const Eigen::Vector3d& r0 = shape.transform().translation();
    MeshGeometry geometry;
    geometry.vertices.reserve(mesh.vertices.size());
    for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
        geometry.vertices.push_back({toFloat(mesh.vertices[k] - r0), toFloat(normals[k])});
    }
    geometry.indices.reserve(3 * mesh.triangles.size());
    for (const auto& triangle : mesh.triangles)
        geometry.indices.insert(geometry.indices.end(), triangle.begin(), triangle.end());
    return geometry;
}

std::shared_ptr<const MeshGeometry> MeshCache::geometry(const GeneralShape& shape) {
    const std::string_view preset = shape.presetName();
    std::vector<PresetParameter> parameters = shape.presetParameters();
    const std::size_t hash = keyHash(shape, preset, parameters);
    const auto [from, to] = entries_.equal_range(hash);
    for (auto it = from; it != to; ++it) {
        Entry& entry = it->second;
        if (entry.kind == shape.kind() && entry.preset == preset && entry.matrix == shape.transform().matrix() &&
            entry.parameters == parameters) {
            entry.used = true;
            return entry.geometry;
        }
    }
    auto made = std::make_shared<const MeshGeometry>(meshGeometry(shape));
    ++made_;
    entries_.emplace(
        hash, Entry{shape.kind(), std::string(preset), std::move(parameters), shape.transform().matrix(), made, true});
    return made;
}

void MeshCache::dropUnused() {
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (!it->second.used) {
            it = entries_.erase(it);
        } else {
            it->second.used = false;
            ++it;
        }
    }
}

}  // namespace dropscope::render
