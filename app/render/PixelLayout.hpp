#pragma once

#include <cstddef>
#include <cstdint>

namespace dropscope::render {

// How a picture's pixels lie in memory: which row comes first and in which order a pixel's four bytes hold its
// channels. OpenGL's textures and framebuffer objects hold row 0 at the bottom (the default here); Mesa's gallium
// drivers keep a window system's framebuffer with its top row first, in the window's channel order: RGBA for an
// OSMesa context asked for OSMESA_RGBA, BGRA for X11's and Wayland's usual 32-bit visuals. A blit between two of
// the same layout is a copy of memory; any other costs llvmpipe a pass of its shaders over every pixel
// (docs/rendering.md, "Handing it over").
struct PixelLayout {
    bool topRowFirst = false;
    bool bgra = false;  // blue in the lowest byte; else red (GL_RGBA, GL_UNSIGNED_BYTE)

    bool operator==(const PixelLayout&) const = default;
};

// The channel (0 red, 1 green, 2 blue, 3 alpha) a pixel of `layout` holds in its byte `byte` (0 the lowest).
constexpr std::size_t channelInByte(std::size_t byte, PixelLayout layout) {
    return layout.bgra && (byte == 0 || byte == 2) ? 2 - byte : byte;
}

// An RGBA8 pixel (red in the lowest byte) as a picture of `layout` holds it: red and blue swapped for BGRA.
constexpr std::uint32_t inByteOrder(std::uint32_t rgba, PixelLayout layout) {
    return layout.bgra ? (rgba & 0xFF00FF00u) | (rgba & 0xFFu) << 16 | (rgba >> 16 & 0xFFu) : rgba;
}

}  // namespace dropscope::render
