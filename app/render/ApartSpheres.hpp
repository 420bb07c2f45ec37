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

// The tests (a sphere against a sphere or a contact) the answer may take per sphere and contact before it gives
// up and calls none apart: a cloud packs some eight spheres a cell, so this leaves room for tenfold crowding.
inline constexpr std::size_t kApartWork = 256;

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
    // 1 for each of setShapes' instances that is apart, else 0. None is apart when anything given is not finite,
    // or when the spheres crowd so few cells that telling would take more than kApartWork tests a sphere and
    // contact (the answer is then only slower to draw, never wrong).
    const std::vector<std::uint8_t>& apart();
    // Whether apart() has been worked out again since the last call of this (the renderer then uploads it).
    bool takeUpdated();

private:
    using Cell = std::array<int, 3>;
    bool buildGrid();
    bool makeGrid(const glm::dvec3& low, const glm::dvec3& high, double side);
    std::size_t slot(const Cell& cell) const;
    Cell cellOf(const glm::vec3& p) const;
    template <class F>
    void forEachSphereInBox(const glm::vec3& low, const glm::vec3& high, F&& f) const;
    template <class F>
    void forEachSphereOnSegment(const glm::vec3& a, const glm::vec3& b, F&& f) const;
    // Clears the flag of every sphere a ball reaches into.
    void touchByBalls(const std::vector<Ball>& balls, std::vector<std::uint8_t>& flags);
    void compute();
    bool computeShapes();
    bool computeLayers();

    std::vector<Ball> spheres_;     // by instance; radius < 0 for an ellipsoid (never apart)
    std::vector<Ball> shapeBalls_;  // the other shapes' bounding balls, the ellipsoids' among them
    std::vector<Ball> markers_;
    std::vector<glm::vec3> segments_;   // two points a segment
    std::vector<glm::vec3> triangles_;  // three points a triangle
    bool finiteShapes_ = true;          // every coordinate and radius given finite, by setter
    bool finiteSegments_ = true;
    bool finiteMarkers_ = true;
    bool finiteTriangles_ = true;
    glm::dvec3 low_{0.0};
    double side_ = 1.0;
    Cell dims_{0, 0, 0};
    std::vector<std::uint32_t> cellStart_;  // the spheres of cell k: cellSpheres_[cellStart_[k] .. cellStart_[k + 1])
    std::vector<std::uint32_t> cellSpheres_;
    bool gridBuilt_ = false;  // false with the spheres too crowded or not finite: none apart
    std::size_t work_ = 0;    // tests made by the computation under way, against its budget
    std::size_t budget_ = 0;
    std::vector<std::uint8_t> shapesApart_;  // apart from the other shapes; worked out again only when they change
    std::vector<std::uint8_t> apart_;
    bool gridDirty_ = true;
    bool shapesDirty_ = true;
    bool dirty_ = true;
    bool updated_ = true;
};

}  // namespace dropscope::render
