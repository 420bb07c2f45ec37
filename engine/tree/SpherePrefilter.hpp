#pragma once

#include "geometry/SphereGeometry.hpp"

#include <cstdint>

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
// The prefilter's own arithmetic is in single precision on coordinates relative to an anchor; its rounding
// moves the perpendicular distance and the distance along the ray by less than 60 u X (u = 2^-24, X the
// larger of |ray origin - anchor|_inf and |centre - anchor|_inf + R over the packed spheres): the slack adds
// this many u X, twice the bound (docs/octree.md).
inline constexpr double kPrefilterFloatSlackUnits = 128.0;
// Spheres whose centre lies farther than this from the anchor, or whose radius is larger, are not packed
// (they keep the exact test alone), and a ray shifted farther than this lets every sphere through, so that no
// single-precision quantity, squares included, can overflow.
inline constexpr double kPrefilterLargestPacked = 1e15;

// Four spheres of one octree cell as structure of arrays in single precision (one cache line), for a
// conservative vectorised test before the exact one, which reads the sphere's own double geometry. Centres
// are relative to the octree's anchor (rounded to nearest); radii are R x kPrefilterRadiusFactor rounded up.
// Unused lanes hold NaN centres, which no ray accepts.
struct alignas(64) SphereBlock {
    static constexpr unsigned kWidth = 4;
    float x[kWidth];
    float y[kWidth];
    float z[kWidth];
    float radius[kWidth];

    // Whether `sphere` can be packed against `anchor` (kPrefilterLargestPacked).
    static bool packable(const SphereGeometry& sphere, const Point& anchor);
    void pack(unsigned lane, const SphereGeometry& sphere, const Point& anchor);
    void clear(unsigned lane);
};

// The ray as the prefilter sees it: shifted along itself to a point q = p + shift d near the anchor, in single
// precision relative to the anchor, with the bounds on the distance along the ray from q rounded outwards.
struct PrefilterRay {
    float origin[3];     // q - anchor
    float direction[3];  // d
    float slack;         // the double slack plus kPrefilterFloatSlackUnits u X, rounded up
    float behind;        // -shift, rounded down: a sphere wholly before this is behind p
    float limit;         // best distance so far + double slack - shift, rounded up (+inf before any hit)
    double shift;        // t of q along the ray from p
    double doubleSlack;  // kPrefilterSlackRelative x the ray's coordinate scale

    // The ray p + t d shifted to t = shift, for spheres packed against `anchor` whose |centre - anchor|_inf + R
    // is at most `packedReach`; `doubleSlack` as above. The limit starts at +inf.
    static PrefilterRay make(const Point& p, const Direction& d, double shift, const Point& anchor, double packedReach,
                             double doubleSlack);
    // Sets the limit for a best distance `best` (from p) so far.
    void setBest(double best);
};

// Bit k is set for each of the first `count` (at most 64) spheres of `blocks` that may give a distance in
// (0, best]: those whose ball of radius R kPrefilterRadiusFactor + slack meets the ray's line, is not
// wholly behind the origin and not wholly beyond the best. Every sphere the exact test would let win is among
// them (docs/octree.md). Runs 8 lanes at once with AVX2 when the CPU has it (runtime dispatch), 4 with SSE2
// otherwise; the results may differ only in rounding far inside the slack.
std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);

// The two implementations behind sphereCandidates, for tests (their bits beyond `count` are unspecified).
// The AVX2 one may run only when cpuHasAvx2().
std::uint64_t sphereCandidatesSse2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);
std::uint64_t sphereCandidatesAvx2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);
bool cpuHasAvx2();

}  // namespace dropscope
