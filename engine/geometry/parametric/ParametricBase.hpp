#pragma once

#include "geometry/SurfaceMesh.hpp"
#include "geometry/Vector.hpp"
#include "geometry/parametric/ParametricSurface.hpp"
#include "geometry/parametric/SurfaceExtremes.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace dropscope {

// The rectangle [u0, u1] x [v0, v1] of a parameter domain.
struct ParameterCell {
    double u0 = 0.0;
    double u1 = 1.0;
    double v0 = 0.0;
    double v1 = 1.0;

    double width() const { return u1 - u0; }
    double height() const { return v1 - v0; }
    double uMid() const { return 0.5 * (u0 + u1); }
    double vMid() const { return 0.5 * (v0 + v1); }
};

// A cell's halves along u, along v, or (both) its four quarters.
struct CellSplit {
    std::array<ParameterCell, 4> parts;
    int count = 0;
};
CellSplit splitCell(const ParameterCell& cell, bool alongU, bool alongV);

// Along which parameters to split a cell: those whose edges (between the patch's corners) are at least half as
// long as the longest. Near a pole the cells then split across it only: splitting around it would make many
// slivers that all contain the pole.
std::pair<bool, bool> splitDirections(const std::array<Point, 4>& corners);

// Componentwise bounds on |r_uu|, |r_uv|, |r_vv| over a cell (sampled maxima times a safety factor).
struct CurvatureBound {
    Eigen::Vector3d uu = Eigen::Vector3d::Zero();
    Eigen::Vector3d uv = Eigen::Vector3d::Zero();
    Eigen::Vector3d vv = Eigen::Vector3d::Zero();
};

// What is known of the patch r(cell), in the base frame.
struct CellPatch {
    ParameterCell cell;
    // Contains the whole patch (ParametricShapeTolerance.hpp says how much margin it carries).
    Eigen::AlignedBox3d box;
    // r at (u0, v0), (u1, v0), (u1, v1), (u0, v1): two triangles that seed Newton.
    std::array<Point, 4> corners;
    // A cone containing the directions of r_u x r_v (either sign) over the cell enlarged by Newton's margin:
    // its unit axis and the sine of its half-angle, 1 when unknown or wider than a half-space.
    Eigen::Vector3d normalAxis = Eigen::Vector3d::UnitZ();
    double normalSpreadSine = 1.0;
    // The patch lies between the planes x . normalAxis = slabLow and = slabHigh (infinite when unknown): with the
    // box, a much tighter container for a flat patch crossed obliquely.
    double slabLow = -std::numeric_limits<double>::infinity();
    double slabHigh = std::numeric_limits<double>::infinity();
};

// A node of the tree over the parameter domain (a quadtree, but a cell next to a pole splits in one direction): leaves
// are the base's cells; an inner node's box is the union of its children's.
struct CellNode {
    CellPatch patch;
    CurvatureBound curvature;      // sampled over this node's cell; sub-cells below a leaf reuse it
    std::int32_t firstChild = -1;  // index of the first of childCount consecutive children; -1 for a leaf
    std::int32_t childCount = 0;   // 2 (split along u or v) or 4
    bool isLeaf() const { return firstChild < 0; }
};

// The sampled second-derivative bound over a cell (ParametricShapeTolerance.hpp: kCurvatureSafety).
CurvatureBound sampleCurvature(const ParametricSurface& surface, const ParameterCell& cell);
// Box, corners and normal cone of the patch over `cell`, given a curvature bound valid over it; boxes are
// padded by `padding` length units.
CellPatch describeCell(const ParametricSurface& surface, const ParameterCell& cell, const CurvatureBound& curvature,
                       double padding);
// The same from a coarser grid (tolerance::parametric::kSubCellSamples): for the cells split on the fly below
// the leaves, where the cost of sampling counts more than the tightness of the box.
CellPatch describeSubCell(const ParametricSurface& surface, const ParameterCell& cell, const CurvatureBound& curvature,
                          double padding);
// True when r_u x r_v is (nearly) zero relative to |r_u| |r_v|, or either is zero: a degenerate point such as a
// pole, where the direction of eq. 1.71 is undefined (or lost to rounding).
bool isDegenerate(const SurfaceJet& jet);

// Everything shapes on one surface share (the shared base of seed 000 1.4), computed
// once by makeParametricBase: the cell tree, orientation, area, signed volume, extremes, mesh and cover.
class ParametricBase {
public:
    // Use makeParametricBase. Throws std::invalid_argument when the surface is null or encloses no volume.
    explicit ParametricBase(std::shared_ptr<const ParametricSurface> surface);

    const ParametricSurface& surface() const { return *surface_; }
    const ParameterDomain& domain() const { return domain_; }

    // +1 when r_u x r_v points outward, -1 when inward (the sign of signedVolume()).
    double orientation() const { return orientation_; }
    // Seed 000 eq. 1.73 (signed) and eq. 1.67.
    double signedVolume() const { return signedVolume_; }
    double area() const { return area_; }
    // Least and greatest x, y, z of the base surface.
    const std::array<ExtremeRange, 3>& extremes() const { return extremes_; }

    // nodes().front() is the root.
    const std::vector<CellNode>& nodes() const { return nodes_; }
    // The padding of every cell box (ParametricShapeTolerance.hpp: kBoxPaddingRelative).
    double boxPadding() const { return boxPadding_; }

    const SurfaceMesh& mesh() const { return mesh_; }
    // The leaves' boxes: together they contain the whole surface.
    const std::vector<Eigen::AlignedBox3d>& cover() const { return cover_; }

    // Whether the edge u = u0, u = u1, v = v0, v = v1 (in that order) of the domain is one point: a pole.
    std::array<bool, 4> poles() const { return {poleAtU0_, poleAtU1_, poleAtV0_, poleAtV1_}; }

    // (u, v) folded into the domain along periodic parameters; clamped to it along the others.
    Eigen::Vector2d wrap(double u, double v) const;
    // The jet at (u, v), folded by wrap() first.
    SurfaceJet jet(double u, double v) const;
    // Seed 000 eq. 1.71 times orientation(): the unit outward normal of the base surface. At a pole (an edge of
    // the domain collapsed to a point) it is the mean over a tiny ring around it, at another degenerate point
    // it is taken a tiny step inside the domain; invalid only if no normal is found that way.
    Direction outwardNormal(double u, double v) const;

private:
    bool collapsedEdge(bool uEdge, double value) const;
    std::int32_t buildNode(std::size_t slot, const ParameterCell& cell, int depth);
    void buildMesh();

    std::shared_ptr<const ParametricSurface> surface_;
    ParameterDomain domain_;
    double orientation_ = 1.0;
    double signedVolume_ = 0.0;
    double area_ = 0.0;
    std::array<ExtremeRange, 3> extremes_{};
    std::vector<CellNode> nodes_;
    double boxPadding_ = 0.0;
    bool poleAtU0_ = false;  // that edge of the domain is one point (a pole)
    bool poleAtU1_ = false;
    bool poleAtV0_ = false;
    bool poleAtV1_ = false;
    SurfaceMesh mesh_;
    std::vector<Eigen::AlignedBox3d> cover_;
};

// Builds the shared base of every shape on `surface` (all the integrals, the tree and the mesh: the
// expensive part, done once).
std::shared_ptr<const ParametricBase> makeParametricBase(std::shared_ptr<const ParametricSurface> surface);

}  // namespace dropscope
