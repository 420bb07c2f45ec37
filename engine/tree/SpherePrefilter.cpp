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

bool SphereLanes::packable(const SphereGeometry& sphere, const PrefilterFrame& frame) {
    return SphereGeometry::make(sphere.center, sphere.radius).band == sphere.band &&
           frame.reach(sphere) * frame.scale <= kPrefilterLargestExtent;
}

void SphereLanes::pack(unsigned lane, const SphereGeometry& sphere, const PrefilterFrame& frame) {
    for (unsigned axis = 0; axis < 3; ++axis) {
        x_[axis * stride_ + lane] = static_cast<float>((sphere.center[axis] - frame.anchor[axis]) * frame.scale);
    }
    radius(lane) = floatAtLeast(sphere.radius * kPrefilterRadiusFactor * frame.scale);
}

void SphereLanes::clear(unsigned lane) {
    for (unsigned axis = 0; axis < 3; ++axis) x_[axis * stride_ + lane] = std::numeric_limits<float>::quiet_NaN();
    radius(lane) = 0.0f;
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

    // Lanes x[0..3] of the four arrays.
    int accept(const float* x, unsigned stride) const {
        const __m128 rx = _mm_sub_ps(_mm_load_ps(x), ox);
        const __m128 ry = _mm_sub_ps(_mm_load_ps(x + stride), oy);
        const __m128 rz = _mm_sub_ps(_mm_load_ps(x + 2 * stride), oz);
        const __m128 b = _mm_add_ps(_mm_add_ps(_mm_mul_ps(rx, dx), _mm_mul_ps(ry, dy)), _mm_mul_ps(rz, dz));
        const __m128 wx = _mm_sub_ps(rx, _mm_mul_ps(b, dx));
        const __m128 wy = _mm_sub_ps(ry, _mm_mul_ps(b, dy));
        const __m128 wz = _mm_sub_ps(rz, _mm_mul_ps(b, dz));
        const __m128 perpendicular2 =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(wx, wx), _mm_mul_ps(wy, wy)), _mm_mul_ps(wz, wz));
        const __m128 reach = _mm_add_ps(_mm_load_ps(x + 3 * stride), slack);
        __m128 ok = _mm_cmple_ps(perpendicular2, _mm_mul_ps(reach, reach));
        ok = _mm_and_ps(ok, _mm_cmpge_ps(_mm_add_ps(b, reach), behind));
        ok = _mm_and_ps(ok, _mm_cmple_ps(_mm_sub_ps(b, reach), limit));
        return _mm_movemask_ps(ok);
    }
};

}  // namespace

std::uint64_t sphereCandidatesSse2(const float* x, unsigned stride, unsigned count, const PrefilterRay& ray) {
    const Sse2Lanes lanes{_mm_set1_ps(ray.origin[0]),    _mm_set1_ps(ray.origin[1]),    _mm_set1_ps(ray.origin[2]),
                          _mm_set1_ps(ray.direction[0]), _mm_set1_ps(ray.direction[1]), _mm_set1_ps(ray.direction[2]),
                          _mm_set1_ps(ray.slack),        _mm_set1_ps(ray.behind),       _mm_set1_ps(ray.limit)};
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += 4) {
        mask |= static_cast<std::uint64_t>(lanes.accept(x + first, stride)) << first;
    }
    return mask;
}

namespace {

// Four floats in both halves.
__attribute__((target("avx2,fma"))) inline __m256 fourTwice(const float* at) {
    return _mm256_broadcast_ps(reinterpret_cast<const __m128*>(at));
}

}  // namespace

// Eight lanes a step; a last step of four (a count 1 to 4 more than a multiple of 8) tests those in both halves.
// The loads do not wait on a test of which step is the last.
__attribute__((target("avx2,fma"))) std::uint64_t sphereCandidatesAvx2(const float* x, unsigned stride, unsigned count,
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
    const auto accept = [&](__m256 sx, __m256 sy, __m256 sz, __m256 sradius) __attribute__((target("avx2,fma"))) {
        const __m256 rx = _mm256_sub_ps(sx, ox);
        const __m256 ry = _mm256_sub_ps(sy, oy);
        const __m256 rz = _mm256_sub_ps(sz, oz);
        const __m256 reach = _mm256_add_ps(sradius, slack);
        const __m256 b = _mm256_fmadd_ps(rz, dz, _mm256_fmadd_ps(ry, dy, _mm256_mul_ps(rx, dx)));
        const __m256 wx = _mm256_fnmadd_ps(b, dx, rx);
        const __m256 wy = _mm256_fnmadd_ps(b, dy, ry);
        const __m256 wz = _mm256_fnmadd_ps(b, dz, rz);
        const __m256 perpendicular2 = _mm256_fmadd_ps(wz, wz, _mm256_fmadd_ps(wy, wy, _mm256_mul_ps(wx, wx)));
        __m256 ok = _mm256_cmp_ps(perpendicular2, _mm256_mul_ps(reach, reach), _CMP_LE_OQ);
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_add_ps(b, reach), behind, _CMP_GE_OQ));
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_sub_ps(b, reach), limit, _CMP_LE_OQ));
        return static_cast<std::uint64_t>(_mm256_movemask_ps(ok));
    };
    std::uint64_t mask = 0;
    unsigned first = 0;
    for (; first + 4 < count; first += 8) {
        const float* at = x + first;
        mask |= accept(_mm256_loadu_ps(at), _mm256_loadu_ps(at + stride), _mm256_loadu_ps(at + 2 * stride),
                       _mm256_loadu_ps(at + 3 * stride))
                << first;
    }
    if (first < count) {
        const float* at = x + first;
        mask |= accept(fourTwice(at), fourTwice(at + stride), fourTwice(at + 2 * stride), fourTwice(at + 3 * stride))
                << first;
    }
    return mask;
}

// Sixteen lanes a step, the AVX2 version's operations in the same order, so the two give the same bits; a last
// step of fewer than 16 lanes loads only those (masked loads, which read nothing beyond them).
__attribute__((target("avx512f"))) std::uint64_t sphereCandidatesAvx512(const float* x, unsigned stride, unsigned count,
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
    const auto accept = [&](__m512 sx, __m512 sy, __m512 sz, __m512 sradius) __attribute__((target("avx512f"))) {
        const __m512 rx = _mm512_sub_ps(sx, ox);
        const __m512 ry = _mm512_sub_ps(sy, oy);
        const __m512 rz = _mm512_sub_ps(sz, oz);
        const __m512 reach = _mm512_add_ps(sradius, slack);
        const __m512 b = _mm512_fmadd_ps(rz, dz, _mm512_fmadd_ps(ry, dy, _mm512_mul_ps(rx, dx)));
        const __m512 wx = _mm512_fnmadd_ps(b, dx, rx);
        const __m512 wy = _mm512_fnmadd_ps(b, dy, ry);
        const __m512 wz = _mm512_fnmadd_ps(b, dz, rz);
        const __m512 perpendicular2 = _mm512_fmadd_ps(wz, wz, _mm512_fmadd_ps(wy, wy, _mm512_mul_ps(wx, wx)));
        __mmask16 ok = _mm512_cmp_ps_mask(perpendicular2, _mm512_mul_ps(reach, reach), _CMP_LE_OQ);
        ok = _mm512_mask_cmp_ps_mask(ok, _mm512_add_ps(b, reach), behind, _CMP_GE_OQ);
        ok = _mm512_mask_cmp_ps_mask(ok, _mm512_sub_ps(b, reach), limit, _CMP_LE_OQ);
        return static_cast<std::uint64_t>(ok);
    };
    std::uint64_t mask = 0;
    unsigned first = 0;
    for (; first + 16 <= count; first += 16) {
        const float* at = x + first;
        mask |= accept(_mm512_loadu_ps(at), _mm512_loadu_ps(at + stride), _mm512_loadu_ps(at + 2 * stride),
                       _mm512_loadu_ps(at + 3 * stride))
                << first;
    }
    if (first < count) {
        const auto some = static_cast<__mmask16>((1u << (count - first)) - 1);
        const float* at = x + first;
        mask |= accept(_mm512_maskz_loadu_ps(some, at), _mm512_maskz_loadu_ps(some, at + stride),
                       _mm512_maskz_loadu_ps(some, at + 2 * stride), _mm512_maskz_loadu_ps(some, at + 3 * stride))
                << first;
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

using Candidates = std::uint64_t (*)(const float*, unsigned, unsigned, const PrefilterRay&);

const Candidates kCandidates = cpuHasAvx512() ? sphereCandidatesAvx512
                               : cpuHasAvx2() ? sphereCandidatesAvx2
                                              : sphereCandidatesSse2;

}  // namespace

std::uint64_t sphereCandidates(const float* x, unsigned stride, unsigned count, bool readAhead,
                               const PrefilterRay& ray) {
    const bool fixed = readAhead && count <= kPrefilterFixedLanes;
    const std::uint64_t mask = kCandidates(x, stride, fixed ? kPrefilterFixedLanes : count, ray);
    return count >= 64 ? mask : mask & ((std::uint64_t{1} << count) - 1);
}

}  // namespace dropscope
