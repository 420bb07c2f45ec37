#include "render/CpuRasteriser.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <system_error>
#include <thread>

namespace dropscope::render {

RasterView rasterView(const Camera& camera, int width, int height) {
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const glm::mat4 projection = camera.projectionMatrix(aspect);
    const glm::mat4 viewProjection = projection * camera.viewMatrix();
    // A point (x, y, -1) of the near plane in normalised device coordinates is inverse(P V) (x, y, -1, 1), whose
    // w does not depend on x and y under a perspective projection: the near plane's point, and the eye ray
    // to it, are affine in the window coordinates.
    const glm::dmat4 unproject = glm::inverse(glm::dmat4(viewProjection));
    const glm::dvec4 nearAtOrigin = unproject * glm::dvec4(-1.0, -1.0, -1.0, 1.0);
    const glm::dvec3 rayAtOrigin = glm::dvec3(nearAtOrigin) / nearAtOrigin.w - camera.eye;
    const glm::dvec3 rayPerPixelX = glm::dvec3(unproject[0]) * (2.0 / width) / nearAtOrigin.w;
    const glm::dvec3 rayPerPixelY = glm::dvec3(unproject[1]) * (2.0 / height) / nearAtOrigin.w;
    const glm::dvec4 eyeClip = glm::dmat4(viewProjection) * glm::dvec4(camera.eye, 1.0);
    RasterView view;
    view.viewProjection = viewProjection;
    view.eye = glm::vec3(camera.eye);
    view.rayAtOrigin = glm::vec3(rayAtOrigin);
    view.rayPerPixelX = glm::vec3(rayPerPixelX);
    view.rayPerPixelY = glm::vec3(rayPerPixelY);
    view.eyeClip = glm::vec2(glm::dvec2(eyeClip.z, eyeClip.w));
    view.clipZ = glm::vec3(viewProjection[0][2], viewProjection[1][2], viewProjection[2][2]);
    view.clipW = glm::vec3(viewProjection[0][3], viewProjection[1][3], viewProjection[2][3]);
    view.pixelsPerUnit = static_cast<float>(projection[1][1] * static_cast<double>(height) / 2.0);
    view.width = width;
    view.height = height;
    return view;
}

RasterSphere rasterSphere(const ShapeInstance& sphere) {
    return {glm::vec3(sphere.center[0], sphere.center[1], sphere.center[2]), sphere.linear[0], sphere.inverseLinear[0],
            sphere.colour};
}

void RasterImage::resize(int width, int height) {
    width_ = std::max(width, 0);
    height_ = std::max(height, 0);
    stride_ = (width_ + kRasterBlock - 1) / kRasterBlock * kRasterBlock;
    const std::size_t pixels = static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height_);
    colour_.resize(pixels);
    depth_.resize(pixels);
}

namespace {

// A channel's value in [0, 1] as its byte of an RGBA8 pixel, at byte `channel`: clamped, times 255, rounded; a NaN
// as 0 (it would make the cast to int undefined; std::max(0, NaN) is 0).
inline std::uint32_t packedChannel(float unit, int channel) {
    const float scaled = std::min(std::max(0.0f, unit * 255.0f + 0.5f), 255.0f);
    return static_cast<std::uint32_t>(static_cast<int>(scaled)) << (8 * channel);
}

}  // namespace

std::uint32_t packColour(const Colour& colour) {
    std::uint32_t packed = 0;
    for (int channel = 0; channel < 4; ++channel)
        packed |= packedChannel(colour[static_cast<std::size_t>(channel)], channel);
    return packed;
}

std::uint32_t RasterImage::pack(const Colour& colour) const { return inByteOrder(packColour(colour), layout_); }

namespace {

// impostor.frag's values for one row of one sphere's pixels: pixel x's eye ray is rowRay + x perPixel.
struct SphereRow {
    float rowRay[3];
    float perPixel[3];
    float objectEye[3];  // the eye in the sphere's unit frame
    float inverseRadius;
    float c;  // |objectEye|^2 - 1
    float eyeClipZ;
    float eyeClipW;
    float clipZ[3];
    float clipW[3];
    // The colour's bytes 0-2 (red, green, blue, or blue, green, red: the image's layout) times 255, at least 0 (NaN
    // taken as 0), clamped to 255 after the shading as a framebuffer clamps. With the sphere's sums finite
    // (spheresBody) the shade is a number, so the cast to int is defined.
    float colour255[3];
    std::uint32_t alpha;  // the colour's alpha, packed (opaque: no opacity applies)
};

// impostor.frag for pixels [from, to) of a row, with the depth test (GL_LESS): the ray in the sphere's unit frame,
// the nearest root in front of the eye (the far one with the eye inside), its depth clamped to [0, 1] as OpenGL
// clamps gl_FragDepth, and the headlight |normal . ray| / |ray|, which on the unit sphere is root / sqrt(a). In
// whole blocks of kRasterBlock pixels from a multiple of it (the image's rows are padded to one), free of
// branches, so the compiler makes each block one vector.
[[gnu::always_inline]] inline void sphereRow(const SphereRow& in, int from, int to, std::uint32_t* __restrict colour,
                                             float* __restrict depth) {
    for (int base = from / kRasterBlock * kRasterBlock; base < to; base += kRasterBlock) {
        for (int lane = 0; lane < kRasterBlock; ++lane) {
            const int x = base + lane;
            const auto fx = static_cast<float>(x);
            const float rx = in.rowRay[0] + fx * in.perPixel[0];
            const float ry = in.rowRay[1] + fx * in.perPixel[1];
            const float rz = in.rowRay[2] + fx * in.perPixel[2];
            const float dx = in.inverseRadius * rx;
            const float dy = in.inverseRadius * ry;
            const float dz = in.inverseRadius * rz;
            const float a = dx * dx + dy * dy + dz * dz;
            const float b = in.objectEye[0] * dx + in.objectEye[1] * dy + in.objectEye[2] * dz;
            const float discriminant = b * b - a * in.c;
            const float root = std::sqrt(std::max(0.0f, discriminant));  // 0 for a NaN too
            const float inverseA = 1.0f / a;
            const float nearRoot = (-b - root) * inverseA;
            const float t = nearRoot >= 0.0f ? nearRoot : (-b + root) * inverseA;
            const float clipZ = in.eyeClipZ + t * (in.clipZ[0] * rx + in.clipZ[1] * ry + in.clipZ[2] * rz);
            const float clipW = in.eyeClipW + t * (in.clipW[0] * rx + in.clipW[1] * ry + in.clipW[2] * rz);
            const float fragmentDepth = std::clamp(0.5f * clipZ / clipW + 0.5f, 0.0f, 1.0f);
            const float shade = 0.3f + 0.7f * (root * std::sqrt(inverseA));
            const std::uint32_t packed =
                static_cast<std::uint32_t>(static_cast<int>(std::min(in.colour255[0] * shade + 0.5f, 255.0f))) |
                static_cast<std::uint32_t>(static_cast<int>(std::min(in.colour255[1] * shade + 0.5f, 255.0f))) << 8 |
                static_cast<std::uint32_t>(static_cast<int>(std::min(in.colour255[2] * shade + 0.5f, 255.0f))) << 16 |
                in.alpha;
            const float before = depth[x];
            const bool drawn = (x >= from) & (x < to) & (discriminant >= 0.0f) & (t >= 0.0f) & (fragmentDepth < before);
            depth[x] = drawn ? fragmentDepth : before;
            colour[x] = drawn ? packed : colour[x];
        }
    }
}

// Where a sphere's pixels can lie: the columns [columnBegin, columnEnd) of the rows [rowBegin, rowEnd); empty when it
// has nothing to draw. Worked out once a frame, for every strip.
struct SpherePlace {
    int columnBegin = 0;
    int columnEnd = 0;
    int rowBegin = 0;
    int rowEnd = 0;
};

[[gnu::always_inline]] inline SpherePlace spherePlace(const RasterSphere& sphere, const RasterView& view) {
    const glm::vec3 toEye = view.eye - sphere.centre;
    const glm::vec3 objectEye = sphere.inverseRadius * toEye;
    const float c = glm::dot(objectEye, objectEye) - 1.0f;
    // Nothing to draw, or a sphere so small beside its distance or the pixels' rays that float's squares of
    // them would overflow (a radius of 1e-18 of the scene's units): left out.
    if (!(sphere.radius > 0.0f) || !(sphere.inverseRadius < 1e18f) || !std::isfinite(c)) return {};
    const float distance = glm::length(toEye);
    const glm::vec4 clipCentre = view.viewProjection * glm::vec4(sphere.centre, 1.0f);
    const float depth = clipCentre.w;        // the centre's distance along the view's axis
    if (depth <= -sphere.radius) return {};  // wholly behind the eye
    SpherePlace place{0, view.width, 0, view.height};
    if (distance > 1.01f * sphere.radius && depth > 1.01f * sphere.radius) {
        // impostor.vert's bound: at angle theta off the axis the silhouette (angular radius alpha) reaches
        // f tan(alpha) s / (1 - tan(theta) tan(alpha)) from the centre's image, s = 1 / cos^2(theta); here with
        // the centre's own theta even outside the view, and half a pixel to spare.
        const float stretch = distance * distance / (depth * depth);
        const float tanAlpha = sphere.radius / std::sqrt(distance * distance - sphere.radius * sphere.radius);
        const float spread = 1.0f - std::sqrt(std::max(stretch - 1.0f, 0.0f)) * tanAlpha;
        if (spread > 0.1f) {
            const float half = view.pixelsPerUnit * tanAlpha * stretch / spread + 0.5f;
            const float x = (clipCentre.x / clipCentre.w * 0.5f + 0.5f) * static_cast<float>(view.width);
            const float y = (clipCentre.y / clipCentre.w * 0.5f + 0.5f) * static_cast<float>(view.height);
            const auto clampTo = [](float v, int high) {  // to [0, high], a NaN to 0
                const auto highest = static_cast<float>(high);
                return static_cast<int>(v > 0.0f ? (v < highest ? v : highest) : 0.0f);
            };
            place.columnBegin = clampTo(std::floor(x - half), view.width);
            place.columnEnd = clampTo(std::ceil(x + half), view.width);
            place.rowBegin = clampTo(std::floor(y - half), view.height);
            place.rowEnd = clampTo(std::ceil(y + half), view.height);
        }
    }
    return place;
}

// The spheres' pixels in rows [rowBegin, rowEnd): each sphere's rows over the columns its place gives.
[[gnu::always_inline]] inline void spheresBody(std::span<const RasterSphere> spheres, const SpherePlace* places,
                                               const RasterView& view, RasterImage& image, int rowBegin, int rowEnd) {
    for (std::size_t index = 0; index < spheres.size(); ++index) {
        const SpherePlace& place = places[index];
        const int columnBegin = place.columnBegin;
        const int columnEnd = place.columnEnd;
        const int rowFrom = std::max(place.rowBegin, rowBegin);
        const int rowTo = std::min(place.rowEnd, rowEnd);
        if (columnBegin >= columnEnd || rowFrom >= rowTo) continue;
        const RasterSphere& sphere = spheres[index];
        const glm::vec3 objectEye = sphere.inverseRadius * (view.eye - sphere.centre);
        const float c = glm::dot(objectEye, objectEye) - 1.0f;
        SphereRow row{};
        for (int k = 0; k < 3; ++k) {
            row.perPixel[k] = view.rayPerPixelX[k];
            row.objectEye[k] = objectEye[k];
            row.clipZ[k] = view.clipZ[k];
            row.clipW[k] = view.clipW[k];
        }
        row.inverseRadius = sphere.inverseRadius;
        row.c = c;
        row.eyeClipZ = view.eyeClip.x;
        row.eyeClipW = view.eyeClip.y;
        for (std::size_t byte = 0; byte < 3; ++byte) {
            row.colour255[byte] = std::max(0.0f, sphere.colour[channelInByte(byte, image.layout())]) * 255.0f;
        }
        row.alpha = packedChannel(sphere.colour[3], 3);
        for (int y = rowFrom; y < rowTo; ++y) {
            const glm::vec3 rowRay =
                view.rayAtOrigin + (static_cast<float>(y) + 0.5f) * view.rayPerPixelY + 0.5f * view.rayPerPixelX;
            for (int k = 0; k < 3; ++k) row.rowRay[k] = rowRay[k];
            sphereRow(row, columnBegin, columnEnd, image.colourRow(y), image.depthRow(y));
        }
    }
}

// A line's end in window coordinates, with what is interpolated along it: the depth linearly on the screen,
// the colour perspective-correctly (its value and 1 over the clip w, linearly).
struct LineEnd {
    float x;
    float y;
    float depth;
    float inverseW;
    float colourOverW[4];
};

LineEnd lineEnd(const glm::vec4& clip, const Colour& colour, const RasterView& view) {
    LineEnd end{};
    end.inverseW = 1.0f / clip.w;
    end.x = (clip.x * end.inverseW * 0.5f + 0.5f) * static_cast<float>(view.width);
    end.y = (clip.y * end.inverseW * 0.5f + 0.5f) * static_cast<float>(view.height);
    end.depth = clip.z * end.inverseW * 0.5f + 0.5f;
    for (std::size_t channel = 0; channel < 4; ++channel) end.colourOverW[channel] = colour[channel] * end.inverseW;
    return end;
}

// How far beyond the image's edges a segment is kept: clipped to |x|, |y| <= kGuardBand w in clip space, so its
// window coordinates stay within a few image widths, where float keeps them to a small fraction of a pixel.
constexpr float kGuardBand = 2.0f;

// The segment a-b clipped in clip space, where every value is linear along it, to the near and far planes
// (-w <= z <= w) and to the guard band about the image. False when nothing is left.
bool clipSegment(glm::vec4& a, Colour& colourA, glm::vec4& b, Colour& colourB) {
    // Each plane as p . (x, y, z, w) >= 0.
    constexpr std::array<glm::vec4, 6> kPlanes{
        glm::vec4(0.0f, 0.0f, 1.0f, 1.0f),       glm::vec4(0.0f, 0.0f, -1.0f, 1.0f),
        glm::vec4(1.0f, 0.0f, 0.0f, kGuardBand), glm::vec4(-1.0f, 0.0f, 0.0f, kGuardBand),
        glm::vec4(0.0f, 1.0f, 0.0f, kGuardBand), glm::vec4(0.0f, -1.0f, 0.0f, kGuardBand)};
    for (const glm::vec4& plane : kPlanes) {
        const float da = glm::dot(plane, a);
        const float db = glm::dot(plane, b);
        if (!std::isfinite(da) || !std::isfinite(db)) return false;
        if (da < 0.0f && db < 0.0f) return false;
        if (da >= 0.0f && db >= 0.0f) continue;
        const float t = da / (da - db);
        const glm::vec4 cut = a + t * (b - a);
        Colour colour;
        for (std::size_t channel = 0; channel < 4; ++channel) {
            colour[channel] = colourA[channel] + t * (colourB[channel] - colourA[channel]);
        }
        if (da < 0.0f) {
            a = cut;
            colourA = colour;
        } else {
            b = cut;
            colourB = colour;
        }
    }
    return a.w > 0.0f && b.w > 0.0f;  // in front of the eye, as the near plane leaves them
}

// A segment as the strips walk it, worked out once a frame: its ends in window coordinates, its major axis, and
// the pixel centres along that axis it takes within the image.
struct LineWalk {
    LineEnd start;
    LineEnd end;
    bool alongX;
    bool flat;  // one colour (most paths): nothing to interpolate
    std::uint32_t flatColour;
    float major0;
    float minor0;
    float slope;
    float minorAtZero;
    float offsetAtZero;
    float depthAtZero;
    float depthPerPixel;
    float inverseLength;
    int first;
    int last;
};

// Rows [begin, end) of the image; empty when begin >= end.
struct RowSpan {
    int begin = 0;
    int end = 0;
};

bool meets(const RowSpan& span, int rowBegin, int rowEnd) { return span.begin < rowEnd && span.end > rowBegin; }

// Segment from-to's walk, and the rows it can draw in (empty when it draws nothing).
[[gnu::always_inline]] inline RowSpan lineWalk(const LineVertex& from, const LineVertex& to, const RasterView& view,
                                               const RasterImage& image, LineWalk& walk) {
    glm::vec4 a = view.viewProjection * glm::vec4(from.position[0], from.position[1], from.position[2], 1.0f);
    glm::vec4 b = view.viewProjection * glm::vec4(to.position[0], to.position[1], to.position[2], 1.0f);
    Colour colourA = from.colour;
    Colour colourB = to.colour;
    if (!clipSegment(a, colourA, b, colourB)) return {};
    walk.start = lineEnd(a, colourA, view);
    walk.end = lineEnd(b, colourB, view);
    const LineEnd& start = walk.start;
    const LineEnd& end = walk.end;
    const float dx = end.x - start.x;
    const float dy = end.y - start.y;
    walk.alongX = std::abs(dx) >= std::abs(dy);
    const bool alongX = walk.alongX;
    walk.major0 = alongX ? start.x : start.y;
    const float major1 = alongX ? end.x : end.y;
    const float majorLength = major1 - walk.major0;
    if (majorLength == 0.0f) return {};
    walk.minor0 = alongX ? start.y : start.x;
    walk.slope = (alongX ? dy : dx) / majorLength;
    // The pixel centres c + 0.5 along the major axis from the start (taken) to the end (not): OpenGL's
    // diamond-exit rule but within a pixel at the two ends.
    const float low = std::min(walk.major0, major1);
    const float high = std::max(walk.major0, major1);
    int first = static_cast<int>(std::ceil(low - 0.5f));
    int last = static_cast<int>(std::ceil(high - 0.5f)) - 1;  // centres below high
    if (majorLength < 0.0f) {                                 // from high down to low: low's centre not taken
        first = static_cast<int>(std::floor(low - 0.5f)) + 1;
        last = static_cast<int>(std::floor(high - 0.5f));
    }
    walk.first = std::max(first, 0);
    walk.last = std::min(last, (alongX ? view.width : view.height) - 1);
    if (walk.first > walk.last) return {};
    walk.inverseLength = 1.0f / majorLength;
    walk.flat = colourA == colourB;
    walk.flatColour = image.pack(colourA);
    // At centre c + 0.5: the minor coordinate minorAtZero + c slope, the depth depthAtZero + c depthPerPixel.
    walk.offsetAtZero = 0.5f - walk.major0;
    walk.minorAtZero = walk.minor0 + walk.offsetAtZero * walk.slope;
    walk.depthPerPixel = (end.depth - start.depth) * walk.inverseLength;
    walk.depthAtZero = start.depth + walk.offsetAtZero * walk.depthPerPixel;
    if (!alongX) return {walk.first, walk.last + 1};
    // The rows the minor coordinate passes through over the centres taken, a row to spare each side (the pixels'
    // own test decides); the guard band keeps these sums within a few image heights.
    const float atFirst = walk.minorAtZero + static_cast<float>(walk.first) * walk.slope;
    const float atLast = walk.minorAtZero + static_cast<float>(walk.last) * walk.slope;
    const float lowest = std::floor(std::min(atFirst, atLast)) - 1.0f;
    const float highest = std::floor(std::max(atFirst, atLast)) + 2.0f;
    const auto height = static_cast<float>(view.height);
    return {static_cast<int>(std::clamp(lowest, 0.0f, height)), static_cast<int>(std::clamp(highest, 0.0f, height))};
}

// The pixels of `walk` in rows [rowBegin, rowEnd).
[[gnu::always_inline]] inline void lineRows(const LineWalk& walk, const RasterView& view, RasterImage& image,
                                            int rowBegin, int rowEnd) {
    const int width = view.width;
    const bool alongX = walk.alongX;
    const float slope = walk.slope;
    // Only the centres whose pixel can lie in the rows and the image: along the major axis directly, along the
    // minor one through the slope (a pixel to spare each side; the pixel's own test below decides).
    int first = std::max(walk.first, alongX ? 0 : rowBegin);
    int last = std::min(walk.last, alongX ? width - 1 : rowEnd - 1);
    const float minorLow = static_cast<float>(alongX ? rowBegin : 0);
    const float minorHigh = static_cast<float>(alongX ? rowEnd : width);
    if (slope != 0.0f) {
        const float atLow = walk.major0 + (minorLow - walk.minor0) / slope - 0.5f;
        const float atHigh = walk.major0 + (minorHigh - walk.minor0) / slope - 0.5f;
        // Clamped before the casts: a slope near 0 puts these far beyond any pixel.
        const float limit = static_cast<float>(alongX ? width : view.height) + 2.0f;
        first = std::max(first, static_cast<int>(std::clamp(std::floor(std::min(atLow, atHigh)), -2.0f, limit)) - 1);
        last = std::min(last, static_cast<int>(std::clamp(std::ceil(std::max(atLow, atHigh)), -2.0f, limit)) + 1);
    } else if (walk.minor0 < minorLow || walk.minor0 >= minorHigh) {
        return;
    }
    const LineEnd& start = walk.start;
    const LineEnd& end = walk.end;
    for (int c = first; c <= last; ++c) {
        const auto fc = static_cast<float>(c);
        // floor for anything above -8, and below it some negative number: a pixel outside either way.
        const int minor = static_cast<int>(walk.minorAtZero + fc * slope + 8.0f) - 8;
        const int x = alongX ? c : minor;
        const int y = alongX ? minor : c;
        if (x < 0 || x >= width || y < rowBegin || y >= rowEnd) continue;
        const float fragmentDepth = walk.depthAtZero + fc * walk.depthPerPixel;
        float& depth = image.depthRow(y)[x];
        if (!(fragmentDepth < depth)) continue;
        depth = fragmentDepth;
        if (walk.flat) {
            image.colourRow(y)[x] = walk.flatColour;
            continue;
        }
        const float along = (fc + walk.offsetAtZero) * walk.inverseLength;  // 0 at the start, 1 at the end
        const float inverseW = start.inverseW + along * (end.inverseW - start.inverseW);
        Colour colour;
        for (std::size_t channel = 0; channel < 4; ++channel) {
            colour[channel] =
                (start.colourOverW[channel] + along * (end.colourOverW[channel] - start.colourOverW[channel])) /
                inverseW;
        }
        image.colourRow(y)[x] = image.pack(colour);
    }
}

// What rasterise works out once a frame for every strip: the spheres' places, the rows each run of kSphereRun
// of them can draw in, and the segments' walks with their rows.
struct FramePlan {
    std::vector<SpherePlace> markerPlaces;
    std::vector<SpherePlace> spherePlaces;
    std::vector<RowSpan> markerRuns;
    std::vector<RowSpan> sphereRuns;
    std::vector<LineWalk> walks;
    std::vector<RowSpan> walkRows;
};

// Spheres come in the Morton order, so a run of consecutive ones lies close together in the picture and a strip
// skips a whole run outside it with one test.
constexpr int kSphereRun = 64;

int runCount(std::size_t spheres) { return static_cast<int>((spheres + kSphereRun - 1) / kSphereRun); }

// Items [begin, end) of some array.
struct IndexRange {
    int begin = 0;
    int end = 0;
};

// Worker `worker` of `workers`' share of `count` items.
IndexRange share(std::size_t count, unsigned worker, unsigned workers) {
    const auto total = static_cast<long long>(count);
    return {static_cast<int>(total * worker / workers), static_cast<int>(total * (worker + 1) / workers)};
}

// The places of the spheres in the runs of `runRange`, and each run's rows.
[[gnu::always_inline]] inline void placeRuns(std::span<const RasterSphere> spheres, const RasterView& view,
                                             SpherePlace* places, RowSpan* runs, const IndexRange& runRange) {
    for (int run = runRange.begin; run < runRange.end; ++run) {
        RowSpan rows{view.height, 0};
        const int end = std::min(static_cast<int>(spheres.size()), (run + 1) * kSphereRun);
        for (int k = run * kSphereRun; k < end; ++k) {
            const SpherePlace place = spherePlace(spheres[static_cast<std::size_t>(k)], view);
            places[k] = place;
            if (place.columnBegin < place.columnEnd && place.rowBegin < place.rowEnd) {
                rows.begin = std::min(rows.begin, place.rowBegin);
                rows.end = std::max(rows.end, place.rowEnd);
            }
        }
        runs[run] = rows;
    }
}

// Worker `worker` of `workers`' share of the plan: places, runs and walks.
[[gnu::always_inline]] inline void planBody(const RasterContent& content, const RasterView& view,
                                            const RasterImage& image, FramePlan& plan, unsigned worker,
                                            unsigned workers) {
    placeRuns(content.markers, view, plan.markerPlaces.data(), plan.markerRuns.data(),
              share(plan.markerRuns.size(), worker, workers));
    placeRuns(content.spheres, view, plan.spherePlaces.data(), plan.sphereRuns.data(),
              share(plan.sphereRuns.size(), worker, workers));
    const IndexRange segments = share(plan.walks.size(), worker, workers);
    for (int k = segments.begin; k < segments.end; ++k) {
        const auto vertex = static_cast<std::size_t>(2 * k);
        plan.walkRows[static_cast<std::size_t>(k)] = lineWalk(content.lines[vertex], content.lines[vertex + 1], view,
                                                              image, plan.walks[static_cast<std::size_t>(k)]);
    }
}

// The spheres of the runs that meet rows [rowBegin, rowEnd), in their order.
[[gnu::always_inline]] inline void spheresInRows(std::span<const RasterSphere> spheres, const SpherePlace* places,
                                                 const std::vector<RowSpan>& runs, const RasterView& view,
                                                 RasterImage& image, int rowBegin, int rowEnd) {
    for (std::size_t run = 0; run < runs.size(); ++run) {
        if (!meets(runs[run], rowBegin, rowEnd)) continue;
        const std::size_t begin = run * kSphereRun;
        const std::size_t count = std::min<std::size_t>(kSphereRun, spheres.size() - begin);
        spheresBody(spheres.subspan(begin, count), places + begin, view, image, rowBegin, rowEnd);
    }
}

// The rows [rowBegin, rowEnd) of the picture: the background, then the markers, the spheres and the lines.
[[gnu::always_inline]] inline void stripBody(const RasterContent& content, const FramePlan& plan,
                                             const RasterView& view, std::uint32_t background, RasterImage& image,
                                             int rowBegin, int rowEnd) {
    for (int y = rowBegin; y < rowEnd; ++y) {  // the rows lie in either order (the layout's)
        std::fill_n(image.colourRow(y), image.stride(), background);
        std::fill_n(image.depthRow(y), image.stride(), 1.0f);
    }
    spheresInRows(content.markers, plan.markerPlaces.data(), plan.markerRuns, view, image, rowBegin, rowEnd);
    spheresInRows(content.spheres, plan.spherePlaces.data(), plan.sphereRuns, view, image, rowBegin, rowEnd);
    for (std::size_t k = 0; k < plan.walks.size(); ++k) {
        if (meets(plan.walkRows[k], rowBegin, rowEnd)) lineRows(plan.walks[k], view, image, rowBegin, rowEnd);
    }
}

// work(worker, workers) for worker 0 to workers - 1 (workers = threads, at least 1), at once: on helper threads
// and this one, or on this one in turn for any no thread is to be had for (a login node's process limit).
void onThreads(unsigned threads, const std::function<void(unsigned, unsigned)>& work) {
    const unsigned workers = std::max(threads, 1u);
    std::vector<std::thread> helpers;
    helpers.reserve(workers - 1);
    for (unsigned k = 1; k < workers; ++k) {
        try {
            helpers.emplace_back(work, k, workers);
        } catch (const std::system_error&) {  // no thread to be had: this one does the share
            work(k, workers);
        }
    }
    work(0, workers);
    for (std::thread& helper : helpers) helper.join();
}

// planBody and stripBody twice: for the x86-64 baseline (SSE2) and for processors with AVX2 and FMA, whose vectors
// hold a whole block of pixels and which fuse multiply-adds: the two round a little differently.
void planBaseline(const RasterContent& content, const RasterView& view, const RasterImage& image, FramePlan& plan,
                  unsigned worker, unsigned workers) {
    planBody(content, view, image, plan, worker, workers);
}

void drawStripBaseline(const RasterContent& content, const FramePlan& plan, const RasterView& view,
                       std::uint32_t background, RasterImage& image, int rowBegin, int rowEnd) {
    stripBody(content, plan, view, background, image, rowBegin, rowEnd);
}

__attribute__((target("avx2,fma"))) void planAvx2(const RasterContent& content, const RasterView& view,
                                                  const RasterImage& image, FramePlan& plan, unsigned worker,
                                                  unsigned workers) {
    planBody(content, view, image, plan, worker, workers);
}

__attribute__((target("avx2,fma"))) void drawStripAvx2(const RasterContent& content, const FramePlan& plan,
                                                       const RasterView& view, std::uint32_t background,
                                                       RasterImage& image, int rowBegin, int rowEnd) {
    stripBody(content, plan, view, background, image, rowBegin, rowEnd);
}

struct RasterCopy {
    void (*plan)(const RasterContent&, const RasterView&, const RasterImage&, FramePlan&, unsigned, unsigned);
    void (*drawStrip)(const RasterContent&, const FramePlan&, const RasterView&, std::uint32_t, RasterImage&, int, int);
};

constexpr RasterCopy kBaselineCopy{planBaseline, drawStripBaseline};

RasterCopy fastestCopy() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? RasterCopy{planAvx2, drawStripAvx2}
                                                                           : kBaselineCopy;
}

const RasterCopy kFastestCopy = fastestCopy();

}  // namespace

bool rasterCodeHasAvx2() { return kFastestCopy.drawStrip == drawStripAvx2; }

unsigned rasterThreads() { return std::clamp(std::thread::hardware_concurrency(), 1u, 8u); }

void rasterise(const RasterContent& content, const RasterView& view, const Colour& background, RasterImage& image,
               unsigned threads, RasterCode code, int stripRows) {
    image.resize(view.width, view.height);
    const std::uint32_t backgroundColour = image.pack(background);
    const RasterCopy copy = code == RasterCode::baseline ? kBaselineCopy : kFastestCopy;
    FramePlan plan;
    plan.markerPlaces.resize(content.markers.size());
    plan.spherePlaces.resize(content.spheres.size());
    plan.markerRuns.resize(static_cast<std::size_t>(runCount(content.markers.size())));
    plan.sphereRuns.resize(static_cast<std::size_t>(runCount(content.spheres.size())));
    plan.walks.resize(content.lines.size() / 2);
    plan.walkRows.resize(content.lines.size() / 2);
    const std::size_t shares =
        std::max({plan.markerRuns.size(), plan.sphereRuns.size(), plan.walks.size(), std::size_t{1}});
    onThreads(static_cast<unsigned>(std::min<std::size_t>(threads, shares)),
              [&](unsigned worker, unsigned workers) { copy.plan(content, view, image, plan, worker, workers); });
    // The strips are taken in turn, so a part of the picture that is busier than another (or a core the machine
    // lends elsewhere for a while) leaves no thread waiting; and the colour and depth of a strip's rows (320 kB
    // at 1280 pixels) stay in a core's own cache while it draws them.
    const int rows = std::max(stripRows, 1);
    const int strips = view.height / rows + (view.height % rows != 0 ? 1 : 0);
    std::atomic<int> nextStrip{0};
    onThreads(std::min(threads, static_cast<unsigned>(std::max(strips, 1))), [&](unsigned, unsigned) {
        for (int strip = nextStrip++; strip < strips; strip = nextStrip++) {
            const int rowBegin = strip * rows;
            copy.drawStrip(content, plan, view, backgroundColour, image, rowBegin,
                           std::min(view.height, rowBegin + rows));
        }
    });
}

void drawInBands(int rows, unsigned threads, const std::function<void(int, int)>& drawRows) {
    const auto bands = std::clamp(threads, 1u, static_cast<unsigned>(std::max(rows, 1)));
    onThreads(bands, [&](unsigned band, unsigned count) {
        const IndexRange span = share(static_cast<std::size_t>(rows), band, count);
        drawRows(span.begin, span.end);
    });
}

}  // namespace dropscope::render
