#pragma once

#include "geometry/SphereGeometry.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace dropscope {

// Absolute slack of the sphere prefilter for the double rounding around it, relative to the ray's coordinate
// scale (|p|_inf plus the largest coordinate of the inflated root): it covers the rounding of the exact
// distanceToSurface and of the ray's shift to its entry point (a few eps of that scale each, ~1e-15), and the
// part 2 x kCoordinateRelative x |centre|_inf (< 3e-14 of the scale) of the spheres' surface bands; 1e-12 is a
// margin of ~30 over the largest of them and widens the test by a negligible 1e-12 of the scene.
// docs/octree.md, "The sphere prefilter", has the derivation.
inline constexpr double kPrefilterSlackRelative = 1e-12;
// The other part of 2 bands, 2 x kSurfaceRelative x R, taken as a factor on the radius (twice that, so
// the rounding of R x factor never matters).
inline constexpr double kPrefilterRadiusFactor = 1.0 + 4.0 * tolerance::kSurfaceRelative;
// The prefilter's own arithmetic is in single precision on coordinates relative to an anchor and scaled by a
// power of two (PrefilterFrame); its rounding moves the perpendicular distance and the distance along the ray
// by less than 60 u X (u = 2^-24, X = |q - anchor|_inf + the largest |centre - anchor|_inf + R of a packed
// sphere, q the ray's shifted origin, in the frame's units): the slack adds 128 u X, about twice the bound
// (docs/octree.md).
inline constexpr double kPrefilterFloatSlackUnits = 128.0;
// The range of X, in the frame's units, within which the prefilter computes: above it a square could overflow,
// below it the slack could fall among single precision's subnormals, whose rounding is absolute. A ray outside
// it lets every sphere through; a sphere that would make X larger is not packed (neither happens with the root
// in the frame's unit cube, short of a sphere 1e12 times smaller than the root right at its centre).
inline constexpr double kPrefilterLargestExtent = 1e15;
inline constexpr double kPrefilterSmallestExtent = 0x1p-40;

// A float no smaller than v, within a few units of single rounding (infinite beyond the largest float; the
// lowest float below it). v is widened by 4 units of single rounding and 2 of the smallest subnormal, more than
// the conversion to the nearest float can take back at any magnitude. Inline and without a branch on the
// rounding: the traversal sets a limit each time its best hit changes.
inline float floatAtLeast(double v) {
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    if (v < -kFloatMax) return -std::numeric_limits<float>::max();
    const double widened = v + std::abs(v) * 0x1p-22 + 0x1p-148;
    return widened > kFloatMax ? std::numeric_limits<float>::infinity() : static_cast<float>(widened);
}

// The frame of the blocks' single-precision coordinates: (x - anchor) x scale, with the anchor at the root's
// centre and the scale a power of two that brings the root's half-side into [1, 2). Scaling by a power of two
// is exact, so the relative error analysis holds whatever the scene's size and position.
struct PrefilterFrame {
    Point anchor = Point::Zero();
    double scale = 1.0;

    static PrefilterFrame around(const Point& centre, double halfSide);
    // |centre - anchor|_inf + R, in scene units: a packed sphere's share of X.
    double reach(const SphereGeometry& sphere) const {
        return (sphere.center - anchor).cwiseAbs().maxCoeff() + sphere.radius;
    }
};

// 64 bytes (one cache line) of the storage of a cell's packed spheres; SphereLanes says what they hold.
struct alignas(64) SphereBlock {
    static constexpr unsigned kWidth = 4;  // spheres a block's worth of storage holds
    float values[4 * kWidth];
};

// A cell's spheres in single precision, for a conservative vectorised test before the exact one, which reads the
// sphere's double centre and radius: `count` spheres in blocksFor(count) blocks, as four arrays of
// strideFor(count) floats (the count rounded up to 4) one after another, x, y, z and radius. Centres are in the
// frame's coordinates (rounded to nearest); radii are R x kPrefilterRadiusFactor x scale rounded up. Unused
// lanes hold NaN centres, which no ray accepts. Sixteen spheres' x (y, z, radius) are then one load, which
// blocks of four spheres each would make four loads and a transposition in registers (docs/octree.md).
class SphereLanes {
public:
    static unsigned strideFor(unsigned count) {
        return (count + SphereBlock::kWidth - 1) / SphereBlock::kWidth * SphereBlock::kWidth;
    }
    static unsigned blocksFor(unsigned count) { return strideFor(count) / SphereBlock::kWidth; }

    SphereLanes(SphereBlock* blocks, unsigned count) : x_(blocks->values), stride_(strideFor(count)) {}

    const float* x() const { return x_; }
    unsigned stride() const { return stride_; }

    // Whether `sphere` can be packed in `frame`: SphereGeometry::make recomputes its band from its centre and
    // radius (the exact test of a candidate does, from the octree's doubles), and its reach in the frame is
    // within kPrefilterLargestExtent.
    static bool packable(const SphereGeometry& sphere, const PrefilterFrame& frame);
    void pack(unsigned lane, const SphereGeometry& sphere, const PrefilterFrame& frame);
    void clear(unsigned lane);
    float& radius(unsigned lane) { return x_[3 * stride_ + lane]; }

private:
    float* x_;
    unsigned stride_;
};

// The ray as the prefilter sees it: shifted along itself to a point q = p + shift d near the anchor, in the
// frame's single-precision coordinates, with the bounds on the distance along the ray from q rounded outwards.
struct PrefilterRay {
    float origin[3];     // (q - anchor) x scale
    float direction[3];  // d
    float slack;         // (the double slack + kPrefilterFloatSlackUnits u X) x scale, rounded up
    float behind;        // -shift x scale, rounded down: a sphere wholly before this is behind p
    float limit;         // (best distance so far + double slack - shift) x scale, rounded up (+inf before any hit)
    double limitOffset;  // the double slack - shift (scene units), which the limit adds to the best distance
    double scale;        // the frame's

    // The ray p + t d shifted to t = shift, for spheres packed in `frame` whose |centre - anchor|_inf + R is at
    // most `packedReach` (scene units, like `doubleSlack`, above). The limit starts at +inf.
    static PrefilterRay make(const Point& p, const Direction& d, double shift, const PrefilterFrame& frame,
                             double packedReach, double doubleSlack) {
        PrefilterRay ray;
        ray.aim(p, d, shift, frame, packedReach, doubleSlack);
        return ray;
    }
    // make() in place: the traversal's ray is read field by field right after, which a copy of the whole
    // struct would make wait on the stores of its parts (a store-forwarding stall).
    void aim(const Point& p, const Direction& d, double shift, const PrefilterFrame& frame, double packedReach,
             double doubleSlack);
    // Sets the limit for a best distance `best` (from p) so far.
    void setBest(double best) { limit = floatAtLeast((best + limitOffset) * scale); }
};

// Bit k is set for each of the first `count` (at most 64) spheres from `x` (x[k], x[stride + k],
// x[2 stride + k], x[3 stride + k]: a cell's SphereLanes, or a later part of them) that may give a distance in
// (0, best]: those whose ball of radius R kPrefilterRadiusFactor + slack meets the ray's line, is not wholly
// behind the origin and not wholly beyond the best. Every sphere the exact test would let win is among them
// (docs/octree.md). Runs 16 lanes at once with AVX-512F, 8 with AVX2, 4 with SSE2 otherwise, the widest the CPU
// has (runtime dispatch); SSE2's results may differ from the others' only in rounding far inside the slack.
// Reads only the first `count` lanes (rounded up to 4) of each array.
//
// With `readAhead` and count at most kPrefilterFixedLanes, the test runs over exactly that many lanes of each
// array and drops the bits beyond count: it may read up to x[3 stride + kPrefilterFixedLanes - 1] (in the
// octree, the next cells' blocks, in cache in a small tree). Cells hold varying numbers of spheres, and a loop that ran
// as many steps as each cell needs would end where the processor mispredicts it (docs/octree.md).
inline constexpr unsigned kPrefilterFixedLanes = 32;
std::uint64_t sphereCandidates(const float* x, unsigned stride, unsigned count, bool readAhead,
                               const PrefilterRay& ray);
inline std::uint64_t sphereCandidates(const SphereLanes& lanes, unsigned count, const PrefilterRay& ray) {
    return sphereCandidates(lanes.x(), lanes.stride(), count, false, ray);
}

// The implementations behind sphereCandidates, for tests (their bits beyond `count` are unspecified). The
// AVX2 one may run only when cpuHasAvx2(), the AVX-512 one only when cpuHasAvx512(); the AVX-512 one gives
// the AVX2 one's bits.
std::uint64_t sphereCandidatesSse2(const float* x, unsigned stride, unsigned count, const PrefilterRay& ray);
std::uint64_t sphereCandidatesAvx2(const float* x, unsigned stride, unsigned count, const PrefilterRay& ray);
std::uint64_t sphereCandidatesAvx512(const float* x, unsigned stride, unsigned count, const PrefilterRay& ray);
bool cpuHasAvx2();
bool cpuHasAvx512();

}  // namespace dropscope
