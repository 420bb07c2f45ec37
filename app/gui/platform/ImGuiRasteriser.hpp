#pragma once

#include "render/CpuRasteriser.hpp"

#include <imgui.h>

namespace dropscope::gui {

// The font atlas as ImGui holds it (ImFontAtlas::GetTexDataAsRGBA32): RGBA, four bytes a texel, rows from the top.
struct AtlasPixels {
    const unsigned char* rgba = nullptr;
    int width = 0;
    int height = 0;
};

// Whether rasteriseImGui draws every command of `data`: triangles over the font atlas (`fontTexture`) and no callbacks.
// A plot or a detector image is an OpenGL texture, which only ImGuiRenderer can draw.
bool rasterisable(const ImDrawData& data, ImTextureID fontTexture);

// ImGui's draw data drawn over `image` (the framebuffer's size) as ImGuiRenderer draws it with OpenGL: each
// command's triangles within its clip rectangle (the scissor box, as OpenGL's is cut from it), a pixel taken where its
// centre lies inside (on an edge, as llvmpipe decides in a window: drawTriangle), the vertex colour times the atlas
// (bilinear, repeating) at
// the interpolated coordinate, blended with straight alpha over what is there (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA;
// alpha GL_ONE, GL_ONE_MINUS_SRC_ALPHA) in 8-bit arithmetic rounded to nearest. The image's rows are cut into
// `threads` bands, drawn at once; any count gives the same picture. docs/gui.md, "ImGui's panels on the processor".
void rasteriseImGui(const ImDrawData& data, const AtlasPixels& atlas, render::RasterImage& image, unsigned threads);

// `count` pixels of a layer that rasteriseImGui drew over transparent black (each channel its colour times coverage,
// the alpha its coverage) blended over `pixels` as that drawing would have blended over them: the layer plus each
// channel times one minus the coverage, rounded as rasteriseImGui rounds. Where one blend made a layer's pixel, the
// same as drawing it over `pixels`; where several, they are combined first, which may round 1 or 2 another way.
void blendCovered(const std::uint32_t* layer, std::uint32_t* pixels, int count);

}  // namespace dropscope::gui
