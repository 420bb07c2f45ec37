#pragma once

#include "geometry/Shape.hpp"
#include "render/Colour.hpp"
#include "tree/RayHit.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace dropscope::render {

// Positions go to the GPU in float, relative to an anchor near the scene (its centre), so a scene far
// from the origin keeps its detail.
struct Anchor {
    Point origin = Point::Zero();
    std::array<float, 3> relative(const Point& p) const {
        const Point r = p - origin;
        return {static_cast<float>(r.x()), static_cast<float>(r.y()), static_cast<float>(r.z())};
    }
};

// One shape as the shaders see it: x = center + linear * u for u on the unit sphere (spheres,
// ellipsoids) or in the cube [-1, 1]^3 (boxes). Matrices column-major, as GLSL reads a mat3.
struct ShapeInstance {
    std::array<float, 3> center;
    std::array<float, 9> linear;
    std::array<float, 9> inverseLinear;
    Colour colour;
};

// One corner of a triangle mesh, as box.vert reads it (locations 0 and 1).
struct MeshVertex {
    std::array<float, 3> position;
    std::array<float, 3> normal;
};

// The triangles of a parametric or implicit shape (GeneralShape::mesh), with its positions relative to
// the shape's translation r0: float keeps the detail of the shape's own size wherever it stands, and a
// shape moved (only r0 changed) keeps its geometry. Counter-clockwise seen from outside.
struct MeshGeometry {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;  // three a triangle
};

// A GeneralShape as drawn: its geometry and an instance placing it (center = r0 relative to the anchor,
// linear = identity), so shapes of one geometry share its buffers (box.vert/.frag, instanced).
struct MeshInstance {
    std::shared_ptr<const MeshGeometry> geometry;
    ShapeInstance instance;
};

struct ShapeInstances {
    std::vector<ShapeInstance> rounded;  // spheres and ellipsoids (impostor.vert/.frag)
    std::vector<ShapeId> roundedIds;
    std::vector<ShapeInstance> boxes;  // box.vert/.frag
    std::vector<ShapeId> boxIds;
    std::vector<MeshInstance> meshes;  // parametric and implicit shapes (box.vert/.frag, indexed)
    std::vector<ShapeId> meshIds;
};

class MeshCache;

// Null slots are skipped; `selected` is drawn in the highlight colour. With a cache, the geometry of a
// GeneralShape comes from it (made once for its base and matrix, however often the scene is uploaded);
// without, it is made afresh.
ShapeInstances buildShapeInstances(const std::vector<std::unique_ptr<Shape>>& shapes, const Anchor& anchor,
                                   ShapeId selected = RayHit::kNone, MeshCache* cache = nullptr);

inline constexpr Colour kHighlight{1.0f, 0.85f, 0.1f, 1.0f};

// The colour a shape's instance is drawn in: kHighlight when selected, else its medium's.
Colour shapeColour(const Shape& shape, bool selected);

// A small sphere for the impostor shaders (event markers).
ShapeInstance sphereInstance(const Point& center, double radius, const Anchor& anchor, const Colour& colour);
// Whether the instance's matrices are exactly r I and I / r in float (equal diagonal, zero elsewhere): a sphere,
// which the renderer's SPHERE programs may draw (docs/rendering.md, "Spheres' points").
bool isSphereInstance(const ShapeInstance& shape);

struct LineVertex {
    std::array<float, 3> position;
    Colour colour;
};

// Coloured segments for line.vert/.frag (GL_LINES: two vertices a segment).
class LineBatch {
public:
    explicit LineBatch(const Anchor& anchor) : anchor_(anchor) {}
    void add(const Point& a, const Point& b, const Colour& colour) { add(a, b, colour, colour); }
    void add(const Point& a, const Point& b, const Colour& colourA, const Colour& colourB) {
        vertices_.push_back({anchor_.relative(a), colourA});
        vertices_.push_back({anchor_.relative(b), colourB});
    }
    // The 12 edges of an axis-aligned box.
    void addBox(const Eigen::AlignedBox3d& box, const Colour& colour);
    // Room for exactly `segments` more segments: for one bulk add, not to be called segment by segment.
    void reserveMore(std::size_t segments) { vertices_.reserve(vertices_.size() + 2 * segments); }
    const std::vector<LineVertex>& vertices() const { return vertices_; }
    bool empty() const { return vertices_.empty(); }

private:
    Anchor anchor_;
    std::vector<LineVertex> vertices_;
};

// Flat-coloured triangles, drawn opaque with the line shaders (GL_TRIANGLES: three vertices a triangle,
// every one of a face in its colour): detector images and fills.
class TriangleBatch {
public:
    explicit TriangleBatch(const Anchor& anchor) : anchor_(anchor) {}
    // The quadrilateral a, b, c, d (in order around it) as two triangles.
    void addQuad(const Point& a, const Point& b, const Point& c, const Point& d, const Colour& colour) {
        for (const Point* corner : {&a, &b, &c, &a, &c, &d}) vertices_.push_back({anchor_.relative(*corner), colour});
    }
    const std::vector<LineVertex>& vertices() const { return vertices_; }
    bool empty() const { return vertices_.empty(); }

private:
    Anchor anchor_;
    std::vector<LineVertex> vertices_;
};

}  // namespace dropscope::render
