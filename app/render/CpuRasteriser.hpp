#pragma once

#include "render/Camera.hpp"
#include "render/Colour.hpp"
#include "render/DrawData.hpp"
#include "render/PixelLayout.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace dropscope::render {

// What the processor needs of a frame's camera: Renderer::draw's numbers for the shaders, the same ones.
struct RasterView {
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};
    // The eye ray through window coordinates (x, y): rayAtOrigin + x rayPerPixelX + y rayPerPixelY.
    glm::vec3 rayAtOrigin{0.0f};
    glm::vec3 rayPerPixelX{0.0f};
    glm::vec3 rayPerPixelY{0.0f};
    // The clip z and w of eye + t ray: eyeClip + t (dot(clipZ, ray), dot(clipW, ray)).
    glm::vec2 eyeClip{0.0f};
    glm::vec3 clipZ{0.0f};
    glm::vec3 clipW{0.0f};
    float pixelsPerUnit = 1.0f;  // framebuffer pixels a unit length spans at unit depth on the axis
    int width = 0;
    int height = 0;
};

// The view of `camera` (in the coordinates the positions are given in) over a width x height framebuffer.
RasterView rasterView(const Camera& camera, int width, int height);

// An opaque sphere as the processor draws it (a ShapeInstance whose matrices are r I and I / r).
struct RasterSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
    float inverseRadius = 0.0f;  // the instance's own I / r, as the shaders read it
    Colour colour{};
};

RasterSphere rasterSphere(const ShapeInstance& sphere);

// A picture drawn on the processor: colour in RGBA8, in the byte order of its layout; the depth of each pixel's
// nearest surface in [0, 1], 1 where nothing was drawn. Pixel (x, y) counts y from the bottom row, as OpenGL
// does, whichever row its layout stores first (OpenGL's own, the bottom, red in the lowest byte, unless set
// otherwise). Rows are `stride` pixels apart, a multiple of kRasterBlock at least `width`, so the spheres are
// drawn in whole blocks of pixels.
inline constexpr int kRasterBlock = 8;

class RasterImage {
public:
    // The size of the next picture; the pixels are left as they were until drawn.
    void resize(int width, int height);
    // How the next picture lies in memory.
    void setLayout(PixelLayout layout) { layout_ = layout; }
    PixelLayout layout() const { return layout_; }
    // A colour as a pixel of this layout holds it (packColour, in its byte order).
    std::uint32_t pack(const Colour& colour) const;
    int width() const { return width_; }
    int height() const { return height_; }
    int stride() const { return stride_; }
    // stride * height pixels, the rows' padding included.
    const std::vector<std::uint32_t>& colour() const { return colour_; }
    const std::vector<float>& depth() const { return depth_; }
    std::uint32_t colourAt(int x, int y) const { return colour_[index(x, y)]; }
    float depthAt(int x, int y) const { return depth_[index(x, y)]; }
    std::uint32_t* colourRow(int y) { return colour_.data() + index(0, y); }
    // The stride x height pixels as they lie in memory (the layout's first row first).
    std::uint32_t* colourData() { return colour_.data(); }
    float* depthRow(int y) { return depth_.data() + index(0, y); }

private:
    std::size_t index(int x, int y) const {
        const int row = layout_.topRowFirst ? height_ - 1 - y : y;
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(stride_) + static_cast<std::size_t>(x);
    }
    PixelLayout layout_;
    int width_ = 0;
    int height_ = 0;
    int stride_ = 0;
    std::vector<std::uint32_t> colour_;
    std::vector<float> depth_;
};

// A colour as an RGBA8 framebuffer stores it (each channel clamped to [0, 1], times 255, rounded), red in the lowest
// byte.
std::uint32_t packColour(const Colour& colour);

// Draws the background, then opaque spheres (the markers among them) and lines (GL_LINES: two vertices a segment)
// into `image`, made the view's size, as Renderer::draw does with the impostor and line programs: a sphere's pixel is
// the eye ray through its centre meeting the sphere, shaded by the same headlight, at its exact depth; a line's pixels
// are those OpenGL's rule for one-pixel lines takes, at the depth and colour interpolated along it; the
// nearest wins (GL_LESS). The rows are cut into strips of `stripRows` (at least 1), which `threads` threads take in
// turn; any count and any strips give the same picture. docs/rendering.md, "Drawn on the processor".
struct RasterContent {
    std::span<const RasterSphere> spheres;
    std::span<const RasterSphere> markers;
    std::span<const LineVertex> lines;
};
// The rows of the picture a thread draws at a time.
inline constexpr int kRasterStripRows = 32;
// Which copy of the drawing code runs: the fastest the processor has (AVX2 where it has it), or the x86-64
// baseline's (for tests: the two draw the same picture but for rounding).
enum class RasterCode { fastest, baseline };
void rasterise(const RasterContent& content, const RasterView& view, const Colour& background, RasterImage& image,
               unsigned threads, RasterCode code = RasterCode::fastest, int stripRows = kRasterStripRows);
// Whether RasterCode::fastest is the AVX2 copy on this processor.
bool rasterCodeHasAvx2();

// The threads a frame drawn on the processor is cut into: the processor's, up to 8.
unsigned rasterThreads();

// drawRows(rowBegin, rowEnd) for `rows` rows cut into min(threads, rows) bands (at least one), drawn at once: on
// helper threads and this one, or on this one when no thread is to be had (a login node's process limit).
void drawInBands(int rows, unsigned threads, const std::function<void(int, int)>& drawRows);

}  // namespace dropscope::render
