#pragma once

#include "render/DrawData.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace dropscope::render {

// How deep another thing must reach into a sphere, as a fraction of its radius, to count: less than this is
// float rounding (a path's end on the sphere's surface, stored anchor-relative in float) and, at the most a
// point is wide (kExactPointPixels), a sixtieth of a pixel.
inline constexpr float kApartReach = 1e-3f;

// The spheres that nothing else drawn reaches into: not another shape, an event marker, a line segment or a
// face (docs/rendering.md, "Spheres apart"). Along any eye ray through such a sphere everything else drawn lies
// before its entry or beyond its exit, so an interactive frame may draw it as a point at its centre's depth and
// still hide and show the rest as its exact depth would, but at its rim (impostor.vert).
//
// The spheres are kept in a uniform grid, each in every cell its bounding box meets, so a contact is tested
// against the spheres of the cells it passes through. The grid and the answer are worked out when asked for
// after a change.
class ApartSpheres {
public:
    struct Ball {
        glm::vec3 centre;
        float radius;
    };

    // The spheres and ellipsoids as the renderer draws them, in its order (only spheres can be apart), and
    // the bounding balls of the other shapes drawn (boxes, meshes).
    void setShapes(const std::vector<ShapeInstance>& rounded, const std::vector<Ball>& otherShapes);
    // The layers drawn with them: segments (two vertices each), event markers, triangles (three vertices each).
    void setSegments(const std::vector<LineVertex>& segments);
    void setMarkers(const std::vector<ShapeInstance>& markers);
    void setTriangles(const std::vector<LineVertex>& triangles);
    // A sphere's or ellipsoid's instance's bounding ball: its largest semi-axis around its centre.
    static Ball boundingBall(const ShapeInstance& rounded);
    // 1 for each of setShapes' instances that is apart, else 0.
    const std::vector<std::uint8_t>& apart();
    // Whether apart() has changed since the last call of this (the renderer then uploads it again).
    bool takeChanged();

private:
    using Cell = std::array<int, 3>;
    void buildGrid();
    bool makeGrid(float side);
    std::size_t slot(const Cell& cell) const;
    Cell cellOf(const glm::vec3& p) const;
    template <class F>
    void forEachSphereInBox(const glm::vec3& low, const glm::vec3& high, F&& f) const;
    template <class F>
    void forEachSphereOnSegment(const glm::vec3& a, const glm::vec3& b, F&& f) const;
    void compute();

    // Clears the flag of every sphere a ball reaches into.
    void touchByBalls(const std::vector<Ball>& balls, std::vector<std::uint8_t>& flags) const;

    std::vector<Ball> spheres_;     // by instance; radius < 0 for an ellipsoid (never apart)
    std::vector<Ball> shapeBalls_;  // the other shapes' bounding balls, the ellipsoids' among them
    std::vector<Ball> markers_;
    std::vector<glm::vec3> segments_;              // two points a segment
    std::vector<std::array<glm::vec3, 2>> boxes_;  // the triangles' bounds (low, high)
    glm::vec3 low_{0.0f};
    float side_ = 1.0f;
    Cell dims_{0, 0, 0};
    std::vector<std::uint32_t> cellStart_;  // the spheres of cell k: cellSpheres_[cellStart_[k] .. cellStart_[k + 1])
    std::vector<std::uint32_t> cellSpheres_;
    std::vector<std::uint8_t> shapesApart_;  // apart from the other shapes; worked out again only when they change
    std::vector<std::uint8_t> apart_;
    bool gridDirty_ = true;
    bool shapesDirty_ = true;
    bool dirty_ = true;
    bool changed_ = true;
};

}  // namespace dropscope::render
