// The conservative vectorised sphere test the octree runs before the exact one
// (docs/octree.md, "The sphere prefilter"). SSE2 is the x86-64 baseline; the AVX2 and AVX-512 variants are
// chosen at run time, so the binary stays portable. Only the candidate mask is computed here: the exact
// distanceToSurface runs in baseline code, so its doubles never depend on the CPU.
#include "tree/SpherePrefilter.hpp"

#include <immintrin.h>
#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope {

namespace {

constexpr float kFloatInfinity = std::numeric_limits<float>::infinity();
// Single precision's unit roundoff, 2^-24.
constexpr double kFloatRoundoff = 0x1p-24;

float floatAtMost(double v) { return -floatAtLeast(-v); }

}  // namespace

PrefilterFrame PrefilterFrame::around(const Point& centre, double halfSide) {
    const bool scalable = halfSide > 0.0 && std::isfinite(halfSide);
    return {centre, scalable ? std::ldexp(1.0, -std::ilogb(halfSide)) : 1.0};
}

bool SphereBlock::packable(const SphereGeometry& sphere, const PrefilterFrame& frame) {
    return SphereGeometry::make(sphere.center, sphere.radius).band == sphere.band &&
           frame.reach(sphere) * frame.scale <= kPrefilterLargestExtent;
}

void SphereBlock::pack(unsigned lane, const SphereGeometry& sphere, const PrefilterFrame& frame) {
    x[lane] = static_cast<float>((sphere.center.x() - frame.anchor.x()) * frame.scale);
    y[lane] = static_cast<float>((sphere.center.y() - frame.anchor.y()) * frame.scale);
    z[lane] = static_cast<float>((sphere.center.z() - frame.anchor.z()) * frame.scale);
    radius[lane] = floatAtLeast(sphere.radius * kPrefilterRadiusFactor * frame.scale);
}

void SphereBlock::clear(unsigned lane) {
    x[lane] = y[lane] = z[lane] = std::numeric_limits<float>::quiet_NaN();
    radius[lane] = 0.0f;
}

void PrefilterRay::aim(const Point& p, const Direction& d, double shift, const PrefilterFrame& frame,
                       double packedReach, double doubleSlack) {
    const Eigen::Vector3d shifted = (p + shift * d.vector() - frame.anchor) * frame.scale;
    const double extent = shifted.cwiseAbs().maxCoeff() + packedReach * frame.scale;  // X
    for (int axis = 0; axis < 3; ++axis) direction[axis] = static_cast<float>(d[axis]);
    behind = floatAtMost(-shift * frame.scale);
    limit = kFloatInfinity;
    limitOffset = doubleSlack - shift;
    scale = frame.scale;
    // Outside the range every sphere passes: from the anchor with an infinite slack, every packed lane passes
    // each comparison.
    if (!(extent <= kPrefilterLargestExtent && extent >= kPrefilterSmallestExtent)) {
        for (float& coordinate : origin) coordinate = 0.0f;
        slack = kFloatInfinity;
        return;
    }
    for (int axis = 0; axis < 3; ++axis) origin[axis] = static_cast<float>(shifted[axis]);
    slack = floatAtLeast(doubleSlack * frame.scale + kPrefilterFloatSlackUnits * kFloatRoundoff * extent);
}

namespace {

// With O = centre - q, b = O.d (distance along the ray from q to the centre's foot), w = O - b d (the
// perpendicular, cancellation-free) and reach = R' + slack, a sphere stays a candidate when |w| <= reach,
// b + reach >= behind and b - reach <= limit. NaN (unused lanes) fails every comparison.
struct Sse2Lanes {
    __m128 ox, oy, oz, dx, dy, dz, slack, behind, limit;

    int accept(const SphereBlock& block) const {
        const __m128 x = _mm_sub_ps(_mm_load_ps(block.x), ox);
        const __m128 y = _mm_sub_ps(_mm_load_ps(block.y), oy);
        const __m128 z = _mm_sub_ps(_mm_load_ps(block.z), oz);
        const __m128 b = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, dx), _mm_mul_ps(y, dy)), _mm_mul_ps(z, dz));
        const __m128 wx = _mm_sub_ps(x, _mm_mul_ps(b, dx));
        const __m128 wy = _mm_sub_ps(y, _mm_mul_ps(b, dy));
        const __m128 wz = _mm_sub_ps(z, _mm_mul_ps(b, dz));
        const __m128 perpendicular2 =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(wx, wx), _mm_mul_ps(wy, wy)), _mm_mul_ps(wz, wz));
        const __m128 reach = _mm_add_ps(_mm_load_ps(block.radius), slack);
        __m128 ok = _mm_cmple_ps(perpendicular2, _mm_mul_ps(reach, reach));
        ok = _mm_and_ps(ok, _mm_cmpge_ps(_mm_add_ps(b, reach), behind));
        ok = _mm_and_ps(ok, _mm_cmple_ps(_mm_sub_ps(b, reach), limit));
        return _mm_movemask_ps(ok);
    }
};

}  // namespace

std::uint64_t sphereCandidatesSse2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray) {
    const Sse2Lanes lanes{_mm_set1_ps(ray.origin[0]),    _mm_set1_ps(ray.origin[1]),    _mm_set1_ps(ray.origin[2]),
                          _mm_set1_ps(ray.direction[0]), _mm_set1_ps(ray.direction[1]), _mm_set1_ps(ray.direction[2]),
                          _mm_set1_ps(ray.slack),        _mm_set1_ps(ray.behind),       _mm_set1_ps(ray.limit)};
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += SphereBlock::kWidth) {
        mask |= static_cast<std::uint64_t>(lanes.accept(blocks[first / SphereBlock::kWidth])) << first;
    }
    return mask;
}

namespace {

// Four floats of one block in the lower half, four of another in the upper.
__attribute__((target("avx2,fma"))) inline __m256 both(const float* low, const float* high) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(low)), _mm_load_ps(high), 1);
}

}  // namespace

// Two blocks a step, one in each half of the registers. The pairs' loads do not wait on a test of which
// block is the last; with an odd number of blocks the last step tests the last block twice (its upper half's
// bits lie beyond count).
__attribute__((target("avx2,fma"))) std::uint64_t sphereCandidatesAvx2(const SphereBlock* blocks, unsigned count,
                                                                       const PrefilterRay& ray) {
    const __m256 ox = _mm256_set1_ps(ray.origin[0]);
    const __m256 oy = _mm256_set1_ps(ray.origin[1]);
    const __m256 oz = _mm256_set1_ps(ray.origin[2]);
    const __m256 dx = _mm256_set1_ps(ray.direction[0]);
    const __m256 dy = _mm256_set1_ps(ray.direction[1]);
    const __m256 dz = _mm256_set1_ps(ray.direction[2]);
    const __m256 slack = _mm256_set1_ps(ray.slack);
    const __m256 behind = _mm256_set1_ps(ray.behind);
    const __m256 limit = _mm256_set1_ps(ray.limit);
    const auto accept = [&](const SphereBlock& low, const SphereBlock& high) __attribute__((target("avx2,fma"))) {
        const __m256 x = _mm256_sub_ps(both(low.x, high.x), ox);
        const __m256 y = _mm256_sub_ps(both(low.y, high.y), oy);
        const __m256 z = _mm256_sub_ps(both(low.z, high.z), oz);
        const __m256 reach = _mm256_add_ps(both(low.radius, high.radius), slack);
        const __m256 b = _mm256_fmadd_ps(z, dz, _mm256_fmadd_ps(y, dy, _mm256_mul_ps(x, dx)));
        const __m256 wx = _mm256_fnmadd_ps(b, dx, x);
        const __m256 wy = _mm256_fnmadd_ps(b, dy, y);
        const __m256 wz = _mm256_fnmadd_ps(b, dz, z);
        const __m256 perpendicular2 = _mm256_fmadd_ps(wz, wz, _mm256_fmadd_ps(wy, wy, _mm256_mul_ps(wx, wx)));
        __m256 ok = _mm256_cmp_ps(perpendicular2, _mm256_mul_ps(reach, reach), _CMP_LE_OQ);
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_add_ps(b, reach), behind, _CMP_GE_OQ));
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_sub_ps(b, reach), limit, _CMP_LE_OQ));
        return static_cast<std::uint64_t>(_mm256_movemask_ps(ok));
    };
    constexpr unsigned kPair = 2 * SphereBlock::kWidth;
    std::uint64_t mask = 0;
    unsigned first = 0;
    for (; first + SphereBlock::kWidth < count; first += kPair) {
        const SphereBlock* pair = blocks + first / SphereBlock::kWidth;
        mask |= accept(pair[0], pair[1]) << first;
    }
    if (first < count) {
        const SphereBlock& last = blocks[first / SphereBlock::kWidth];
        mask |= accept(last, last) << first;
    }
    return mask;
}

namespace {

// Lanes (a, b, c, d) of the result: a and b from `first`'s lanes, c and d from `second`'s. The masked form
// with every lane set: GCC 12 warns of the undefined vector that the plain form passes itself.
template <int kLanes>
__attribute__((target("avx512f"))) inline __m512 shuffleLanes(__m512 first, __m512 second) {
    return _mm512_mask_shuffle_f32x4(first, 0xffff, first, second, kLanes);
}

struct Avx512Spheres {
    __m512 x, y, z, radius;
};

// The 4 x 4 transposition of 128-bit lanes that takes four blocks (x, y, z, radius each) to the x, y, z and
// radius of their 16 spheres, block k in lane k.
__attribute__((target("avx512f"))) inline Avx512Spheres transpose(const SphereBlock* b0, const SphereBlock* b1,
                                                                  const SphereBlock* b2, const SphereBlock* b3) {
    const __m512 r0 = _mm512_load_ps(b0);
    const __m512 r1 = _mm512_load_ps(b1);
    const __m512 r2 = _mm512_load_ps(b2);
    const __m512 r3 = _mm512_load_ps(b3);
    const __m512 xy01 = shuffleLanes<_MM_SHUFFLE(1, 0, 1, 0)>(r0, r1);  // x0 y0 x1 y1
    const __m512 zr01 = shuffleLanes<_MM_SHUFFLE(3, 2, 3, 2)>(r0, r1);  // z0 r0 z1 r1
    const __m512 xy23 = shuffleLanes<_MM_SHUFFLE(1, 0, 1, 0)>(r2, r3);
    const __m512 zr23 = shuffleLanes<_MM_SHUFFLE(3, 2, 3, 2)>(r2, r3);
    return {shuffleLanes<_MM_SHUFFLE(2, 0, 2, 0)>(xy01, xy23), shuffleLanes<_MM_SHUFFLE(3, 1, 3, 1)>(xy01, xy23),
            shuffleLanes<_MM_SHUFFLE(2, 0, 2, 0)>(zr01, zr23), shuffleLanes<_MM_SHUFFLE(3, 1, 3, 1)>(zr01, zr23)};
}

}  // namespace

// Four blocks a step, transposed in registers; the same operations in the same order as the AVX2 version,
// so the two give the same bits. A last step of fewer than 16 spheres (one to four blocks) fills the lanes
// of the blocks it lacks with its last block again (their bits lie beyond count).
__attribute__((target("avx512f"))) std::uint64_t sphereCandidatesAvx512(const SphereBlock* blocks, unsigned count,
                                                                        const PrefilterRay& ray) {
    const __m512 ox = _mm512_set1_ps(ray.origin[0]);
    const __m512 oy = _mm512_set1_ps(ray.origin[1]);
    const __m512 oz = _mm512_set1_ps(ray.origin[2]);
    const __m512 dx = _mm512_set1_ps(ray.direction[0]);
    const __m512 dy = _mm512_set1_ps(ray.direction[1]);
    const __m512 dz = _mm512_set1_ps(ray.direction[2]);
    const __m512 slack = _mm512_set1_ps(ray.slack);
    const __m512 behind = _mm512_set1_ps(ray.behind);
    const __m512 limit = _mm512_set1_ps(ray.limit);
    const auto accept = [&](const Avx512Spheres& spheres) __attribute__((target("avx512f"))) {
        const __m512 x = _mm512_sub_ps(spheres.x, ox);
        const __m512 y = _mm512_sub_ps(spheres.y, oy);
        const __m512 z = _mm512_sub_ps(spheres.z, oz);
        const __m512 reach = _mm512_add_ps(spheres.radius, slack);
        const __m512 b = _mm512_fmadd_ps(z, dz, _mm512_fmadd_ps(y, dy, _mm512_mul_ps(x, dx)));
        const __m512 wx = _mm512_fnmadd_ps(b, dx, x);
        const __m512 wy = _mm512_fnmadd_ps(b, dy, y);
        const __m512 wz = _mm512_fnmadd_ps(b, dz, z);
        const __m512 perpendicular2 = _mm512_fmadd_ps(wz, wz, _mm512_fmadd_ps(wy, wy, _mm512_mul_ps(wx, wx)));
        __mmask16 ok = _mm512_cmp_ps_mask(perpendicular2, _mm512_mul_ps(reach, reach), _CMP_LE_OQ);
        ok = _mm512_mask_cmp_ps_mask(ok, _mm512_add_ps(b, reach), behind, _CMP_GE_OQ);
        ok = _mm512_mask_cmp_ps_mask(ok, _mm512_sub_ps(b, reach), limit, _CMP_LE_OQ);
        return static_cast<std::uint64_t>(ok);
    };
    constexpr unsigned kQuad = 4 * SphereBlock::kWidth;
    std::uint64_t mask = 0;
    unsigned first = 0;
    for (; first + kQuad <= count; first += kQuad) {
        const SphereBlock* quad = blocks + first / SphereBlock::kWidth;
        mask |= accept(transpose(quad, quad + 1, quad + 2, quad + 3)) << first;
    }
    if (first < count) {
        const SphereBlock* rest = blocks + first / SphereBlock::kWidth;
        const unsigned last = (count - first - 1) / SphereBlock::kWidth;  // the last block's index here, 0-3
        mask |= accept(transpose(rest, rest + std::min(1u, last), rest + std::min(2u, last), rest + last)) << first;
    }
    return mask;
}

bool cpuHasAvx512() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f");
}

bool cpuHasAvx2() {
    __builtin_cpu_init();  // required before __builtin_cpu_supports in a static initialiser
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

namespace {

using Candidates = std::uint64_t (*)(const SphereBlock*, unsigned, const PrefilterRay&);

const Candidates kCandidates = cpuHasAvx512() ? sphereCandidatesAvx512
                               : cpuHasAvx2() ? sphereCandidatesAvx2
                                              : sphereCandidatesSse2;

}  // namespace

std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, bool readAhead, const PrefilterRay& ray) {
    const bool fixed = readAhead && count <= kPrefilterFixedLanes;
    const std::uint64_t mask = kCandidates(blocks, fixed ? kPrefilterFixedLanes : count, ray);
    return count >= 64 ? mask : mask & ((std::uint64_t{1} << count) - 1);
}

}  // namespace dropscope
