#pragma once

#include "render/CpuRasteriser.hpp"
#include "render/PixelLayout.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace dropscope::test {

// Every layout a framebuffer may have: the bottom row or the top one first, RGBA or BGRA.
inline constexpr std::array<render::PixelLayout, 4> kEveryLayout{
    {{false, false}, {false, true}, {true, false}, {true, true}}};

// A layout in words, for a test's trace.
inline std::string layoutName(render::PixelLayout layout) {
    return std::string(layout.topRowFirst ? "top row first, " : "bottom row first, ") + (layout.bgra ? "BGRA" : "RGBA");
}

// The pixels where `image`, read from memory row by row, is not `reference` (a picture of the same size and stride
// in OpenGL's own layout) as `image`'s layout lays it out: the rows in that order, each colour in that byte order,
// and with `withDepth` the same depth.
inline int differingInMemory(const render::RasterImage& image, const render::RasterImage& reference, bool withDepth) {
    const render::PixelLayout layout = image.layout();
    int differing = 0;
    for (int row = 0; row < image.height(); ++row) {
        const int y = layout.topRowFirst ? image.height() - 1 - row : row;
        for (int x = 0; x < image.width(); ++x) {
            const auto at = static_cast<std::size_t>(row * image.stride() + x);
            const bool same = image.colour()[at] == render::inByteOrder(reference.colourAt(x, y), layout) &&
                              (!withDepth || image.depth()[at] == reference.depthAt(x, y));
            differing += same ? 0 : 1;
        }
    }
    return differing;
}

}  // namespace dropscope::test
