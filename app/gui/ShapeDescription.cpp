#include "gui/ShapeDescription.hpp"

#include <cstddef>
#include <cstdio>
#include <functional>
#include <numeric>

namespace dropscope::gui {

namespace {

// Vectors up to this long are shown whole; longer ones by their length.
constexpr std::size_t kShownVectorLength = 4;
// Lists of up to this many points are shown whole; longer ones by their count.
constexpr std::size_t kShownPoints = 3;
// A bicubic Bezier control net: 4 x 4 points of 3 coordinates.
constexpr std::size_t kNetPoints = 16;

std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

std::string tuple(const std::vector<double>& values, std::size_t from, std::size_t count) {
    std::string out = "(";
    for (std::size_t k = 0; k < count; ++k) out += (k > 0 ? ", " : "") + number(values[from + k]);
    return out + ")";
}

std::string joinedExtents(const std::vector<std::size_t>& extents, std::size_t count) {
    std::string out;
    for (std::size_t k = 0; k < count; ++k) out += (k > 0 ? " x " : "") + std::to_string(extents[k]);
    return out;
}

}  // namespace

std::string presetParameterText(const PresetParameter& parameter) {
    const std::vector<std::size_t>& extents = parameter.extents;
    const std::vector<double>& values = parameter.values;
    const std::size_t expected =
        std::accumulate(extents.begin(), extents.end(), std::size_t{1}, std::multiplies<std::size_t>());
    if (values.size() != expected) return std::to_string(values.size()) + " numbers";
    if (extents.empty()) return number(values[0]);
    if (extents.size() == 1) {
        return extents[0] <= kShownVectorLength ? tuple(values, 0, extents[0])
                                                : std::to_string(extents[0]) + " numbers";
    }
    const std::size_t rank = extents.size();
    if (rank >= 3 && extents[rank - 2] == kNetPoints && extents[rank - 1] == 3) {
        return joinedExtents(extents, rank - 2) + " patches";
    }
    if (rank == 2 && extents[1] == 3) {
        if (extents[0] > kShownPoints) return std::to_string(extents[0]) + " points";
        std::string out;
        for (std::size_t k = 0; k < extents[0]; ++k) out += (k > 0 ? ", " : "") + tuple(values, 3 * k, 3);
        return out;
    }
    return joinedExtents(extents, rank) + " numbers";
}

std::array<std::string, 3> matrixRows(const Eigen::Matrix3d& m) {
    std::array<std::string, 3> rows;
    for (int row = 0; row < 3; ++row) {
        rows[static_cast<std::size_t>(row)] = tuple({m(row, 0), m(row, 1), m(row, 2)}, 0, 3);
    }
    return rows;
}

}  // namespace dropscope::gui
