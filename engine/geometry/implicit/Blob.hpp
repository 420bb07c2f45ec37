#pragma once

#include "geometry/implicit/ImplicitFunction.hpp"

#include <vector>

namespace dropscope {

// Droplets merging: the smooth union of spheres, through the log-sum-exp smooth minimum of their
// signed distances d_i = |r - c_i| - R_i,
//   f = -k ln sum_i exp(-d_i / k)      (k > 0: the blend length).
// grad f = sum_i w_i (r - c_i)/|r - c_i| with softmax weights w_i >= 0 summing to 1: a convex
// combination of unit vectors, so |grad f| <= 1 and L = 1. Since the sum lies between the largest term
// exp(-min d / k) and n times it, min d - k ln n <= f <= min d: the blob contains every sphere and
// lies inside the spheres grown by k ln n. Preset "blob" {centers [[x, y, z], ...], radii [...], blend}.
class Blob final : public ImplicitFunction {
public:
    // Throws std::invalid_argument unless there are >= 2 centres, as many radii, all finite, the radii
    // > 0 and the blend finite and > 0.
    Blob(std::vector<Point> centers, std::vector<double> radii, double blend);

    const std::vector<Point>& centers() const { return centers_; }
    const std::vector<double>& radii() const { return radii_; }
    double blend() const { return blend_; }

    double value(const Point& r) const override;
    Eigen::Vector3d gradient(const Point& r) const override;
    double lipschitzBound() const override { return 1.0; }
    Eigen::AlignedBox3d bounds() const override;
    double characteristicLength() const override;
    std::string_view presetName() const override { return "blob"; }
    std::vector<PresetParameter> presetParameters() const override;

private:
    std::vector<Point> centers_;
    std::vector<double> radii_;
    double blend_;
};

}  // namespace dropscope
