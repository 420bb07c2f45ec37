#pragma once

#include "geometry/SphereGeometry.hpp"

#include <cstdint>

namespace dropscope {

// Absolute slack of the sphere prefilter, relative to the ray's coordinate scale (|p|_inf plus the
// largest coordinate of the inflated root): it covers the double rounding of the prefilter's own
// arithmetic and of the exact distanceToSurface (a few eps of that scale each, ~1e-15), and the part
// 2 x kCoordinateRelative x |centre|_inf (< 3e-14 of the scale) of the spheres' surface bands; 1e-12 is a
// margin of ~30 over the largest of them and widens the test by a negligible 1e-12 of the scene.
// docs/octree.md, "The sphere prefilter", has the derivation.
inline constexpr double kPrefilterSlackRelative = 1e-12;
// The other part of 2 bands, 2 x kSurfaceRelative x R, taken as a factor on the radius (twice that, so
// the rounding of R x factor never matters).
inline constexpr double kPrefilterRadiusFactor = 1.0 + 4.0 * tolerance::kSurfaceRelative;

// Four spheres of one octree cell as structure of arrays (two cache lines), for a vectorised test before
// the exact one. A sphere's band is not stored: SphereGeometry::make(centre, radius) recomputes it,
// bit for bit (the octree checks that it does when it packs a sphere). Unused lanes hold NaN centres,
// which no ray accepts.
struct alignas(64) SphereBlock {
    static constexpr unsigned kWidth = 4;
    double x[kWidth];
    double y[kWidth];
    double z[kWidth];
    double radius[kWidth];

    // Whether `sphere` can be packed: its band is the one make() recomputes.
    static bool packable(const SphereGeometry& sphere) {
        return SphereGeometry::make(sphere.center, sphere.radius).band == sphere.band;
    }
    void pack(unsigned lane, const SphereGeometry& sphere);
    void clear(unsigned lane);
    SphereGeometry geometry(unsigned lane) const {
        return SphereGeometry::make({x[lane], y[lane], z[lane]}, radius[lane]);
    }
};

// The ray as the prefilter sees it.
struct PrefilterRay {
    double origin[3];     // p
    double direction[3];  // d
    double slack;         // kPrefilterSlackRelative x the ray's coordinate scale
    double limit;         // best distance so far + slack (+inf before any hit)
};

// Bit k is set for each of the first `count` (at most 64) spheres of `blocks` that may give a distance in
// (0, limit]: those whose ball of radius R kPrefilterRadiusFactor + slack meets the ray's line, is not
// wholly behind the origin and not wholly beyond `limit`. Every sphere the exact test would let win is
// among them (docs/octree.md). Runs 4 lanes at once with AVX2 when the CPU has it (runtime dispatch),
// 2 with SSE2 otherwise; the results may differ only in rounding far inside the slack.
std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);

// The two implementations behind sphereCandidates, for tests (their bits beyond `count` are unspecified).
// The AVX2 one may run only when cpuHasAvx2().
std::uint64_t sphereCandidatesSse2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);
std::uint64_t sphereCandidatesAvx2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);
bool cpuHasAvx2();

}  // namespace dropscope
