#include "render/Guides.hpp"

#include <algorithm>
#include <cmath>

namespace dropscope::render {

namespace {

constexpr double kGridCover = 1.5;   // the grid's width over the bounds' larger extent
constexpr double kGridCells = 10.0;  // cells a side, about
constexpr double kGridDrop = 0.01;   // gap under the bounds, of the grid's width: off any box face

// The smallest of 1, 2, 5 times a power of ten that is at least `x`.
double niceStep(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * decade >= x) return m * decade;
    }
    return 10.0 * decade;
}

}  // namespace

void addAxes(LineBatch& lines, const Point& origin, double length) {
    lines.add(origin, origin + length * Eigen::Vector3d::UnitX(), kAxisX);
    lines.add(origin, origin + length * Eigen::Vector3d::UnitY(), kAxisY);
    lines.add(origin, origin + length * Eigen::Vector3d::UnitZ(), kAxisZ);
}

void addGroundGrid(LineBatch& lines, const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& up) {
    if (bounds.isEmpty()) return;
    Eigen::Index normal = 0;
    up.cwiseAbs().maxCoeff(&normal);
    const Eigen::Index a = (normal + 1) % 3;
    const Eigen::Index b = (normal + 2) % 3;
    const Eigen::Vector3d size = bounds.sizes();
    const double width = kGridCover * std::max({size[a], size[b], 1e-9});
    const double step = niceStep(width / kGridCells);
    const int half = static_cast<int>(std::ceil(0.5 * width / step));
    // Under the bounds: below their lowest point along `up`, whichever way up points.
    const bool upwards = up[normal] >= 0.0;
    const double level = upwards ? bounds.min()[normal] - kGridDrop * width : bounds.max()[normal] + kGridDrop * width;
    const Point center = bounds.center();
    const double centerA = step * std::round(center[a] / step);
    const double centerB = step * std::round(center[b] / step);
    const auto at = [&](double u, double v) {
        Point p;
        p[normal] = level;
        p[a] = u;
        p[b] = v;
        return p;
    };
    const double extent = half * step;
    for (int k = -half; k <= half; ++k) {
        const double offset = k * step;
        lines.add(at(centerA + offset, centerB - extent), at(centerA + offset, centerB + extent), kGridColour);
        lines.add(at(centerA - extent, centerB + offset), at(centerA + extent, centerB + offset), kGridColour);
    }
}

}  // namespace dropscope::render
