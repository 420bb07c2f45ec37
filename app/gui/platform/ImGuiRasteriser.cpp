#include "gui/platform/ImGuiRasteriser.hpp"

#include "gui/platform/ImGuiClip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <emmintrin.h>

namespace dropscope::gui {

namespace {

// x y / 255 rounded to nearest, exact for bytes x and y.
inline std::uint32_t timesByte(std::uint32_t x, std::uint32_t y) {
    const std::uint32_t t = x * y + 0x80u;
    return (t + (t >> 8)) >> 8;
}

// A straight-alpha RGBA8 colour's share of a blend over what is under it: each colour channel times alpha, and
// alpha itself (GL_SRC_ALPHA for colour, GL_ONE for alpha).
inline std::uint32_t ownShare(std::uint32_t colour) {
    const std::uint32_t alpha = colour >> 24;
    return timesByte(colour & 0xFFu, alpha) | timesByte(colour >> 8 & 0xFFu, alpha) << 8 |
           timesByte(colour >> 16 & 0xFFu, alpha) << 16 | alpha << 24;
}

// Each byte of `under` times `rest` / 255, rounded (timesByte), two bytes at a time in 16-bit lanes: x rest + 0x80
// stays below 2^16, so no lane carries into the next.
inline std::uint32_t scaled(std::uint32_t under, std::uint32_t rest) {
    std::uint32_t evens = (under & 0x00FF00FFu) * rest + 0x00800080u;
    std::uint32_t odds = (under >> 8 & 0x00FF00FFu) * rest + 0x00800080u;
    evens = (evens + (evens >> 8 & 0x00FF00FFu)) >> 8 & 0x00FF00FFu;
    odds = (odds + (odds >> 8 & 0x00FF00FFu)) & 0xFF00FF00u;
    return evens | odds;
}

// `share` (ownShare of a colour of alpha `alpha`) blended over `under`: each byte's two terms add to at most 255
// (round(c a / 255) <= a and round(d (255 - a) / 255) <= 255 - a), so the bytes add without carries.
inline std::uint32_t over(std::uint32_t share, std::uint32_t alpha, std::uint32_t under) {
    return share + scaled(under, 255u - alpha);
}

inline std::uint32_t over(std::uint32_t colour, std::uint32_t under) {
    return over(ownShare(colour), colour >> 24, under);
}

// A coordinate within reach of int (ImGui's lie within a few window sizes), a NaN as 0.
inline float bounded(float edge) { return std::isnan(edge) ? 0.0f : std::clamp(edge, -1e6f, 1e6f); }

// A value in [0, 1] as a byte, rounded to nearest (a NaN as 0).
inline std::uint32_t toByte(float unit) {
    return static_cast<std::uint32_t>((unit > 0.0f ? std::min(unit, 1.0f) : 0.0f) * 255.0f + 0.5f);
}

struct Rgba {
    float channel[4];
};

Rgba unpack(ImU32 colour) {
    Rgba out{};
    for (int k = 0; k < 4; ++k) out.channel[k] = static_cast<float>(colour >> (8 * k) & 0xFFu) * (1.0f / 255.0f);
    return out;
}

// texture(atlas, (u, v)) with GL_LINEAR filtering and GL_REPEAT wrapping, as OpenGL samples it.
Rgba sample(const AtlasPixels& atlas, float u, float v) {
    const float x = u * static_cast<float>(atlas.width) - 0.5f;
    const float y = v * static_cast<float>(atlas.height) - 0.5f;
    const float x0 = std::floor(x);
    const float y0 = std::floor(y);
    const float fx = x - x0;
    const float fy = y - y0;
    const auto wrap = [](int index, int size) {
        if (index >= 0 && index < size) return index;
        const int i = index % size;
        return i < 0 ? i + size : i;
    };
    const int ix = static_cast<int>(bounded(x0));
    const int iy = static_cast<int>(bounded(y0));
    const int xs[2] = {wrap(ix, atlas.width), wrap(ix + 1, atlas.width)};
    const int ys[2] = {wrap(iy, atlas.height), wrap(iy + 1, atlas.height)};
    Rgba out{};
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const float weight = (i == 0 ? 1.0f - fx : fx) * (j == 0 ? 1.0f - fy : fy);
            if (weight == 0.0f) continue;
            const unsigned char* texel =
                atlas.rgba + 4 * (static_cast<std::size_t>(ys[j]) * static_cast<std::size_t>(atlas.width) +
                                  static_cast<std::size_t>(xs[i]));
            for (int k = 0; k < 4; ++k) out.channel[k] += weight * static_cast<float>(texel[k]) * (1.0f / 255.0f);
        }
    }
    return out;
}

// The fragment shader's colour (the vertex colour times the atlas) as the framebuffer's bytes.
inline std::uint32_t fragment(const Rgba& vertex, const Rgba& texel) {
    std::uint32_t out = 0;
    for (int k = 0; k < 4; ++k) out |= toByte(vertex.channel[k] * texel.channel[k]) << (8 * k);
    return out;
}

// Pixels in rows counted from the top, [top, bottom) x [left, right): a command's scissor box within a band.
struct PixelBox {
    int left, top, right, bottom;
    bool empty() const { return right <= left || bottom <= top; }
};

struct Vertex {
    float x, y, u, v;
    ImU32 colour;
};

Vertex vertexAt(const ImDrawData& data, const ImDrawVert& vertex) {
    return {(vertex.pos.x - data.DisplayPos.x) * data.FramebufferScale.x,
            (vertex.pos.y - data.DisplayPos.y) * data.FramebufferScale.y, vertex.uv.x, vertex.uv.y, vertex.col};
}

// The first column whose pixel centre lies at or right of `edge`.
inline int firstCentreFrom(float edge) { return static_cast<int>(std::ceil(bounded(edge) - 0.5f)); }
// The first row whose pixel centre lies below `edge` (ImGui's y grows downwards).
inline int firstCentreBelow(float edge) { return static_cast<int>(std::floor(bounded(edge) - 0.5f)) + 1; }

// An axis-aligned quad of one colour whose atlas coordinates are affine across it (ImDrawList::PrimRect and
// PrimRectUV: corners a, (c.x, a.y), c, (a.x, c.y), drawn as a b c and a c d): the two triangles' pixels are the
// rectangle's, whose centres lie within it (on its edges, those of the left and the bottom one: drawTriangle), with
// the same values.
void drawRectangle(const Vertex& a, const Vertex& c, const AtlasPixels& atlas, const PixelBox& box,
                   render::RasterImage& image) {
    const int left = std::max(firstCentreFrom(std::min(a.x, c.x)), box.left);
    const int right = std::min(firstCentreFrom(std::max(a.x, c.x)), box.right);
    const int top = std::max(firstCentreBelow(std::min(a.y, c.y)), box.top);
    const int bottom = std::min(firstCentreBelow(std::max(a.y, c.y)), box.bottom);
    if (left >= right || top >= bottom) return;
    const Rgba colour = unpack(a.colour);
    const int height = image.height();
    if (a.u == c.u && a.v == c.v) {  // one texel for the whole rectangle: a solid fill
        const std::uint32_t filled = render::inByteOrder(fragment(colour, sample(atlas, a.u, a.v)), image.layout());
        const std::uint32_t alpha = filled >> 24;
        if (alpha == 0) return;
        const std::uint32_t share = ownShare(filled);
        const auto rest = static_cast<std::uint16_t>(255u - alpha);
        for (int row = top; row < bottom; ++row) {
            std::uint32_t* pixels = image.colourRow(height - 1 - row);
            if (alpha == 255u) {
                std::fill(pixels + left, pixels + right, share);
                continue;
            }
            // over() a byte at a time in 16-bit arithmetic, which the baseline's vectors multiply, then the share.
            auto* bytes = reinterpret_cast<std::uint8_t*>(pixels + left);
            const int count = 4 * (right - left);
            for (int i = 0; i < count; ++i) {
                const auto t = static_cast<std::uint16_t>(bytes[i] * rest + 0x80u);
                bytes[i] = static_cast<std::uint8_t>(static_cast<std::uint16_t>(t + (t >> 8)) >> 8);
            }
            for (int x = left; x < right; ++x) pixels[x] += share;
        }
        return;
    }
    const float uPerPixel = (c.u - a.u) / (c.x - a.x);
    const float vPerPixel = (c.v - a.v) / (c.y - a.y);
    // A glyph drawn at its size: a texel a pixel, each pixel's centre on a texel's, so filtering gives the texel.
    const float firstU =
        (a.u + (static_cast<float>(left) + 0.5f - a.x) * uPerPixel) * static_cast<float>(atlas.width) - 0.5f;
    const float firstV =
        (a.v + (static_cast<float>(top) + 0.5f - a.y) * vPerPixel) * static_cast<float>(atlas.height) - 0.5f;
    if (uPerPixel * static_cast<float>(atlas.width) == 1.0f && vPerPixel * static_cast<float>(atlas.height) == 1.0f &&
        firstU == std::floor(firstU) && firstV == std::floor(firstV) && firstU >= 0.0f && firstV >= 0.0f &&
        firstU + static_cast<float>(right - left) <= static_cast<float>(atlas.width) &&
        firstV + static_cast<float>(bottom - top) <= static_cast<float>(atlas.height)) {
        const auto texelX = static_cast<std::size_t>(firstU);
        const auto texelY = static_cast<std::size_t>(firstV);
        const std::uint32_t tint[4] = {a.colour & 0xFFu, a.colour >> 8 & 0xFFu, a.colour >> 16 & 0xFFu, a.colour >> 24};
        const std::size_t low = render::channelInByte(0, image.layout());  // the channels in bytes 0 and 2
        const std::size_t high = render::channelInByte(2, image.layout());
        for (int row = top; row < bottom; ++row) {
            std::uint32_t* pixels = image.colourRow(height - 1 - row);
            const unsigned char* texels =
                atlas.rgba +
                4 * ((texelY + static_cast<std::size_t>(row - top)) * static_cast<std::size_t>(atlas.width) + texelX);
            for (int x = left; x < right; ++x, texels += 4) {
                const std::uint32_t alpha = timesByte(tint[3], texels[3]);
                if (alpha == 0) continue;
                const std::uint32_t drawn = timesByte(tint[low], texels[low]) | timesByte(tint[1], texels[1]) << 8 |
                                            timesByte(tint[high], texels[high]) << 16 | alpha << 24;
                pixels[x] = over(drawn, pixels[x]);
            }
        }
        return;
    }
    for (int row = top; row < bottom; ++row) {
        std::uint32_t* pixels = image.colourRow(height - 1 - row);
        const float v = a.v + (static_cast<float>(row) + 0.5f - a.y) * vPerPixel;
        for (int x = left; x < right; ++x) {
            const float u = a.u + (static_cast<float>(x) + 0.5f - a.x) * uPerPixel;
            const std::uint32_t drawn = render::inByteOrder(fragment(colour, sample(atlas, u, v)), image.layout());
            if (drawn >> 24 != 0) pixels[x] = over(drawn, pixels[x]);
        }
    }
}

// Any triangle: the pixels whose centres lie inside, with the colour and atlas coordinate interpolated linearly
// (ImGui's positions are projected orthographically, so linear is what OpenGL interpolates). A centre on an edge
// goes to the triangle on its right or, on a level edge, above it on the screen: what llvmpipe does in a window's
// framebuffer, which Mesa keeps with its top row first (its "bottom edge rule"; tested on edges through centres).
void drawTriangle(const Vertex& p0, const Vertex& p1, const Vertex& p2, const AtlasPixels& atlas, const PixelBox& box,
                  render::RasterImage& image) {
    const Vertex* v[3] = {&p0, &p1, &p2};
    const auto cross = [](const Vertex& a, const Vertex& b, float x, float y) {
        return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
    };
    float area = cross(*v[0], *v[1], v[2]->x, v[2]->y);
    if (!(area != 0.0f) || !std::isfinite(area)) return;
    if (area < 0.0f) {
        std::swap(v[1], v[2]);
        area = -area;
    }
    const float minX = std::min({v[0]->x, v[1]->x, v[2]->x});
    const float maxX = std::max({v[0]->x, v[1]->x, v[2]->x});
    const float minY = std::min({v[0]->y, v[1]->y, v[2]->y});
    const float maxY = std::max({v[0]->y, v[1]->y, v[2]->y});
    const int left = std::max(firstCentreFrom(minX), box.left);
    const int right = std::min(firstCentreFrom(maxX) + 1, box.right);
    const int top = std::max(firstCentreFrom(minY), box.top);
    const int bottom = std::min(firstCentreFrom(maxY) + 1, box.bottom);
    if (left >= right || top >= bottom) return;
    // Edge k runs from v[k + 1] to v[k + 2]; its function is area's share of the vertex opposite, v[k]. With the
    // positive orientation (y down), a level edge running along -x has the triangle above it, and an edge running
    // up (-y) has it on its right.
    std::array<bool, 3> inclusive{};
    for (int k = 0; k < 3; ++k) {
        const Vertex& from = *v[(k + 1) % 3];
        const Vertex& to = *v[(k + 2) % 3];
        const float dx = to.x - from.x;
        const float dy = to.y - from.y;
        inclusive[static_cast<std::size_t>(k)] = (dy == 0.0f && dx < 0.0f) || dy < 0.0f;
    }
    const Rgba colours[3] = {unpack(v[0]->colour), unpack(v[1]->colour), unpack(v[2]->colour)};
    // The atlas's white pixel under an edge's fringe, or any one texel: sampled once.
    const bool oneTexel = v[0]->u == v[1]->u && v[0]->u == v[2]->u && v[0]->v == v[1]->v && v[0]->v == v[2]->v;
    const Rgba texel = oneTexel ? sample(atlas, v[0]->u, v[0]->v) : Rgba{};
    const float inverseArea = 1.0f / area;
    const int height = image.height();
    const render::PixelLayout layout = image.layout();  // blending is the same byte by byte in either order
    for (int row = top; row < bottom; ++row) {
        const float y = static_cast<float>(row) + 0.5f;
        // The row's span: each edge function is linear along it, -dy px + (dx (y - y0) + dy x0), so where it is
        // at least 0 is one side of a point. The pixels a column either side of the span are tested too, so the
        // test alone (not the span's rounding) decides every pixel.
        float from = static_cast<float>(left);
        float to = static_cast<float>(right);
        for (int k = 0; k < 3; ++k) {
            const Vertex& a = *v[(k + 1) % 3];
            const Vertex& b = *v[(k + 2) % 3];
            const float slope = a.y - b.y;
            const float atZero = (b.x - a.x) * (y - a.y) + (b.y - a.y) * a.x;
            if (slope > 0.0f) {
                from = std::max(from, -atZero / slope - 1.5f);
            } else if (slope < 0.0f) {
                to = std::min(to, -atZero / slope + 0.5f);
            } else if (atZero < 0.0f) {
                to = from;
            }
        }
        const int spanLeft = std::max(left, static_cast<int>(bounded(from)));
        const int spanRight = std::min(right, static_cast<int>(bounded(to)) + 1);
        std::uint32_t* pixels = image.colourRow(height - 1 - row);
        for (int x = spanLeft; x < spanRight; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            float weight[3];
            bool inside = true;
            for (int k = 0; k < 3; ++k) {
                const float e = cross(*v[(k + 1) % 3], *v[(k + 2) % 3], px, y);
                inside = inside && (e > 0.0f || (e == 0.0f && inclusive[static_cast<std::size_t>(k)]));
                weight[k] = e * inverseArea;
            }
            if (!inside) continue;
            Rgba colour{};
            for (int c = 0; c < 4; ++c) {
                colour.channel[c] = weight[0] * colours[0].channel[c] + weight[1] * colours[1].channel[c] +
                                    weight[2] * colours[2].channel[c];
            }
            const float u = weight[0] * v[0]->u + weight[1] * v[1]->u + weight[2] * v[2]->u;
            const float w = weight[0] * v[0]->v + weight[1] * v[1]->v + weight[2] * v[2]->v;
            const std::uint32_t drawn =
                render::inByteOrder(fragment(colour, oneTexel ? texel : sample(atlas, u, w)), layout);
            if (drawn >> 24 != 0) pixels[x] = over(drawn, pixels[x]);
        }
    }
}

// Whether indices i .. i + 5 draw the quad PrimRect and PrimRectUV make, of one colour and affine coordinates.
bool isRectangle(const ImDrawIdx* index, const ImDrawVert* vertices) {
    if (index[1] != index[0] + 1 || index[2] != index[0] + 2 || index[3] != index[0] || index[4] != index[0] + 2 ||
        index[5] != index[0] + 3) {
        return false;
    }
    const ImDrawVert* q = vertices + index[0];
    return q[0].pos.y == q[1].pos.y && q[1].pos.x == q[2].pos.x && q[2].pos.y == q[3].pos.y &&
           q[3].pos.x == q[0].pos.x && q[0].col == q[1].col && q[0].col == q[2].col && q[0].col == q[3].col &&
           q[1].uv.x == q[2].uv.x && q[1].uv.y == q[0].uv.y && q[3].uv.x == q[0].uv.x && q[3].uv.y == q[2].uv.y &&
           q[0].pos.x != q[2].pos.x && q[0].pos.y != q[2].pos.y;
}

void drawBand(const ImDrawData& data, const AtlasPixels& atlas, render::RasterImage& image, int bandTop,
              int bandBottom) {
    const int width = image.width();
    const int height = image.height();
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        for (const ImDrawCmd& command : list.CmdBuffer) {
            const ScissorBox scissor = scissorBox(data, command.ClipRect, width, height);
            const PixelBox box{scissor.x, std::max(height - (scissor.y + scissor.height), bandTop),
                               scissor.x + scissor.width, std::min(height - scissor.y, bandBottom)};
            if (box.empty()) continue;
            const ImDrawIdx* indices = list.IdxBuffer.Data + command.IdxOffset;
            const ImDrawVert* vertices = list.VtxBuffer.Data + command.VtxOffset;
            for (unsigned i = 0; i + 2 < command.ElemCount; i += 3) {
                if (i + 5 < command.ElemCount && isRectangle(indices + i, vertices)) {
                    drawRectangle(vertexAt(data, vertices[indices[i]]), vertexAt(data, vertices[indices[i] + 2]), atlas,
                                  box, image);
                    i += 3;
                    continue;
                }
                drawTriangle(vertexAt(data, vertices[indices[i]]), vertexAt(data, vertices[indices[i + 1]]),
                             vertexAt(data, vertices[indices[i + 2]]), atlas, box, image);
            }
        }
    }
}

}  // namespace

bool rasterisable(const ImDrawData& data, ImTextureID fontTexture) {
    for (int n = 0; n < data.CmdListsCount; ++n) {
        for (const ImDrawCmd& command : data.CmdLists[n]->CmdBuffer) {
            if (command.UserCallback || (command.ElemCount > 0 && command.GetTexID() != fontTexture)) return false;
        }
    }
    return true;
}

void blendCovered(const std::uint32_t* layer, std::uint32_t* pixels, int count) {
    // Four pixels at a time, each channel in a 16-bit lane: timesByte's x y + 0x80 and its sum with itself shifted
    // right by 8 stay below 2^16, and the layer's byte and the product's add without carries (over).
    const __m128i zero = _mm_setzero_si128();
    const __m128i full = _mm_set1_epi16(255);
    const __m128i half = _mm_set1_epi16(0x80);
    const auto scaledPair = [&](__m128i under, __m128i rest) {  // two pixels' channels times their rest, rounded
        const __m128i t = _mm_add_epi16(_mm_mullo_epi16(under, rest), half);
        return _mm_srli_epi16(_mm_add_epi16(t, _mm_srli_epi16(t, 8)), 8);
    };
    int x = 0;
    for (; x + 4 <= count; x += 4) {
        const __m128i share = _mm_loadu_si128(reinterpret_cast<const __m128i*>(layer + x));
        const __m128i under = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pixels + x));
        const __m128i alpha = _mm_srli_epi32(share, 24);
        const __m128i alphas = _mm_or_si128(alpha, _mm_slli_epi32(alpha, 16));  // each pixel's alpha in two lanes
        const __m128i low =
            scaledPair(_mm_unpacklo_epi8(under, zero), _mm_sub_epi16(full, _mm_unpacklo_epi32(alphas, alphas)));
        const __m128i high =
            scaledPair(_mm_unpackhi_epi8(under, zero), _mm_sub_epi16(full, _mm_unpackhi_epi32(alphas, alphas)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(pixels + x), _mm_add_epi8(share, _mm_packus_epi16(low, high)));
    }
    for (; x < count; ++x) pixels[x] = over(layer[x], layer[x] >> 24, pixels[x]);
}

void rasteriseImGui(const ImDrawData& data, const AtlasPixels& atlas, render::RasterImage& image, unsigned threads) {
    const int height = image.height();
    if (height <= 0 || image.width() <= 0 || atlas.rgba == nullptr || atlas.width <= 0 || atlas.height <= 0) return;
    render::drawInBands(height, threads,
                        [&](int rowBegin, int rowEnd) { drawBand(data, atlas, image, rowBegin, rowEnd); });
}

}  // namespace dropscope::gui
