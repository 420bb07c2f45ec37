#pragma once

#include "geometry/parametric/ParametricPresets.hpp"
#include "geometry/parametric/ParametricSurface.hpp"

#include <cstddef>
#include <vector>

namespace dropscope {

// A closed surface of bicubic Bezier patches (seed 003 1.2): patches[row][column] covers u in
// [row, row + 1], v in [column, column + 1]; within it r = sum_ij B_i(u - row) B_j(v - column) net[i][j]
// with the Bernstein basis B_0..B_3 (seed 003 1.1.4). Derivatives are analytic; across a patch seam they
// are those of the patch on the seam's upper side (the surface is only as smooth there as the net makes it).
//
// Edges of a patch: bottom = net[0][*] (its lowest u), top = net[3][*], left = net[*][0] (lowest v),
// right = net[*][3]. The constructor checks, within tolerance::surface::kBezierEdgeRelative times the
// net's size, that the patches close up, and throws std::invalid_argument naming the patch otherwise:
//  - every control point is finite, at least one patch, all rows as long;
//  - each patch's left edge is its left neighbour's right edge, and the first column's left edge is the
//    last column's right edge (the v seam): periodic in v;
//  - each patch's bottom edge is the top edge of the patch below it;
//  - the u = 0 edge (row 0's bottom) and the u = rows edge (last row's top) are each either one point
//    (a pole) or, both, the same curve (periodic in u).
// A pole's control points are then set to exactly its first one, so that r_v vanishes there exactly.
class BezierSurface final : public ParametricSurface {
public:
    explicit BezierSurface(std::vector<std::vector<BezierNet>> patches);

    std::size_t rows() const { return patches_.size(); }
    std::size_t columns() const { return patches_.front().size(); }
    const std::vector<std::vector<BezierNet>>& patches() const { return patches_; }

    ParameterDomain domain() const override;
    Point point(double u, double v) const override;
    SurfaceJet jet(double u, double v) const override;
    SurfaceHessians hessians(double u, double v) const override;

    bool periodicInU() const override { return periodicInU_; }
    bool periodicInV() const override { return true; }
    // The largest edge of the control points' bounding box (the surface lies in their convex hull).
    double characteristicLength() const override { return size_; }
    std::string_view presetName() const override { return "bezier"; }
    // {"patches", {rows, columns, 4, 4, 3}, ...}: the nested arrays patches[row][column][i][j][xyz].
    std::vector<PresetParameter> presetParameters() const override;

private:
    void validate();

    std::vector<std::vector<BezierNet>> patches_;
    double size_ = 0.0;
    bool periodicInU_ = false;
};

}  // namespace dropscope
