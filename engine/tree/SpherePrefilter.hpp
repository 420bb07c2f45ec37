#pragma once

#include "geometry/SphereGeometry.hpp"

#include <cstdint>

namespace dropscope {

// Absolute slack of the sphere prefilter, relative to the ray's coordinate scale (|p|_inf plus the
// largest coordinate of the inflated root): it covers the double rounding of the prefilter's own
// arithmetic and of the exact distanceToSurface (a few eps of that scale each, i.e. ~1e-15); 1e-12 is a
// margin of ~1e3 over them and widens the test by a negligible 1e-12 of the scene. docs/octree.md,
// "The sphere prefilter", has the derivation.
inline constexpr double kPrefilterSlackRelative = 1e-12;

// Four spheres of one octree cell in single precision (one cache line), for a conservative test before
// the exact one: centres relative to the cell's centre, rounded to nearest, and a radius rounded up so
// that it covers R + 2 band plus the distance the rounding moved the centre. Unused lanes hold NaN
// centres, which no ray accepts.
struct alignas(64) SphereBlock {
    static constexpr unsigned kWidth = 4;
    float x[kWidth];
    float y[kWidth];
    float z[kWidth];
    float radius[kWidth];

    // Stores `sphere` in `lane`, relative to `cellCentre`.
    void pack(unsigned lane, const SphereGeometry& sphere, const Point& cellCentre);
    void clear(unsigned lane);
};

// The ray as the prefilter sees it, in the frame of the cell's centre.
struct PrefilterRay {
    double origin[3];     // p - cell centre
    double direction[3];  // d
    double slack;         // kPrefilterSlackRelative x the ray's coordinate scale
    double limit;         // best distance so far + slack (+inf before any hit)
};

// Bit k is set for each of the first `count` (at most 64) spheres of `blocks` that may give a distance in
// (0, limit]: those whose inflated float ball (radius + slack) meets the ray's line, not wholly behind the
// origin, and not wholly beyond `limit`. Every sphere the exact test would let win is among them.
// Runs 4 lanes at once with AVX2 when the CPU has it (runtime dispatch), 2 with SSE2 otherwise.
std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray);

}  // namespace dropscope
