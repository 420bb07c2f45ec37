// The conservative vectorised sphere test the octree runs before the exact one
// (docs/octree.md, "The sphere prefilter"). SSE2 is the x86-64 baseline; the AVX2 variant is chosen at
// run time, so the binary stays portable. Only the candidate mask is computed here: the exact
// distanceToSurface runs in baseline code, so its doubles never depend on the CPU.
#include "tree/SpherePrefilter.hpp"

#include <immintrin.h>
#include <cmath>
#include <limits>

namespace dropscope {

void SphereBlock::pack(unsigned lane, const SphereGeometry& sphere) {
    x[lane] = sphere.center.x();
    y[lane] = sphere.center.y();
    z[lane] = sphere.center.z();
    radius[lane] = sphere.radius;
}

void SphereBlock::clear(unsigned lane) {
    x[lane] = y[lane] = z[lane] = std::numeric_limits<double>::quiet_NaN();
    radius[lane] = 0.0;
}

namespace {

// With O = centre - origin, b = O.d (distance along the ray to the centre's foot), w = O - b d (the
// perpendicular, cancellation-free) and reach = R kPrefilterRadiusFactor + slack, a sphere stays a
// candidate when |w| <= reach, b >= -reach and b - reach <= limit. NaN (unused lanes) fails every
// comparison.
struct Sse2Lanes {
    __m128d ox, oy, oz, dx, dy, dz, factor, slack, limit;

    int accept(__m128d cx, __m128d cy, __m128d cz, __m128d r) const {
        const __m128d x = _mm_sub_pd(cx, ox);
        const __m128d y = _mm_sub_pd(cy, oy);
        const __m128d z = _mm_sub_pd(cz, oz);
        const __m128d b = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, dx), _mm_mul_pd(y, dy)), _mm_mul_pd(z, dz));
        const __m128d wx = _mm_sub_pd(x, _mm_mul_pd(b, dx));
        const __m128d wy = _mm_sub_pd(y, _mm_mul_pd(b, dy));
        const __m128d wz = _mm_sub_pd(z, _mm_mul_pd(b, dz));
        const __m128d perpendicular2 =
            _mm_add_pd(_mm_add_pd(_mm_mul_pd(wx, wx), _mm_mul_pd(wy, wy)), _mm_mul_pd(wz, wz));
        const __m128d reach = _mm_add_pd(_mm_mul_pd(r, factor), slack);
        __m128d ok = _mm_cmple_pd(perpendicular2, _mm_mul_pd(reach, reach));
        ok = _mm_and_pd(ok, _mm_cmpge_pd(_mm_add_pd(b, reach), _mm_setzero_pd()));
        ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_sub_pd(b, reach), limit));
        return _mm_movemask_pd(ok);
    }
};

}  // namespace

std::uint64_t sphereCandidatesSse2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray) {
    const Sse2Lanes lanes{
        _mm_set1_pd(ray.origin[0]),          _mm_set1_pd(ray.origin[1]),    _mm_set1_pd(ray.origin[2]),
        _mm_set1_pd(ray.direction[0]),       _mm_set1_pd(ray.direction[1]), _mm_set1_pd(ray.direction[2]),
        _mm_set1_pd(kPrefilterRadiusFactor), _mm_set1_pd(ray.slack),        _mm_set1_pd(ray.limit)};
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += SphereBlock::kWidth) {
        const SphereBlock& block = blocks[first / SphereBlock::kWidth];
        const int low =
            lanes.accept(_mm_load_pd(block.x), _mm_load_pd(block.y), _mm_load_pd(block.z), _mm_load_pd(block.radius));
        const int high = lanes.accept(_mm_load_pd(block.x + 2), _mm_load_pd(block.y + 2), _mm_load_pd(block.z + 2),
                                      _mm_load_pd(block.radius + 2));
        mask |= static_cast<std::uint64_t>(low | high << 2) << first;
    }
    return mask;
}

__attribute__((target("avx2,fma"))) std::uint64_t sphereCandidatesAvx2(const SphereBlock* blocks, unsigned count,
                                                                       const PrefilterRay& ray) {
    const __m256d ox = _mm256_set1_pd(ray.origin[0]);
    const __m256d oy = _mm256_set1_pd(ray.origin[1]);
    const __m256d oz = _mm256_set1_pd(ray.origin[2]);
    const __m256d dx = _mm256_set1_pd(ray.direction[0]);
    const __m256d dy = _mm256_set1_pd(ray.direction[1]);
    const __m256d dz = _mm256_set1_pd(ray.direction[2]);
    const __m256d factor = _mm256_set1_pd(kPrefilterRadiusFactor);
    const __m256d slack = _mm256_set1_pd(ray.slack);
    const __m256d limit = _mm256_set1_pd(ray.limit);
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += SphereBlock::kWidth) {
        const SphereBlock& block = blocks[first / SphereBlock::kWidth];
        const __m256d x = _mm256_sub_pd(_mm256_load_pd(block.x), ox);
        const __m256d y = _mm256_sub_pd(_mm256_load_pd(block.y), oy);
        const __m256d z = _mm256_sub_pd(_mm256_load_pd(block.z), oz);
        const __m256d reach = _mm256_fmadd_pd(_mm256_load_pd(block.radius), factor, slack);
        const __m256d b = _mm256_fmadd_pd(z, dz, _mm256_fmadd_pd(y, dy, _mm256_mul_pd(x, dx)));
        const __m256d wx = _mm256_fnmadd_pd(b, dx, x);
        const __m256d wy = _mm256_fnmadd_pd(b, dy, y);
        const __m256d wz = _mm256_fnmadd_pd(b, dz, z);
        const __m256d perpendicular2 = _mm256_fmadd_pd(wz, wz, _mm256_fmadd_pd(wy, wy, _mm256_mul_pd(wx, wx)));
        __m256d ok = _mm256_cmp_pd(perpendicular2, _mm256_mul_pd(reach, reach), _CMP_LE_OQ);
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_add_pd(b, reach), _mm256_setzero_pd(), _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_sub_pd(b, reach), limit, _CMP_LE_OQ));
        mask |= static_cast<std::uint64_t>(_mm256_movemask_pd(ok)) << first;
    }
    return mask;
}

bool cpuHasAvx2() {
    __builtin_cpu_init();  // required before __builtin_cpu_supports in a static initialiser
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

namespace {

using Candidates = std::uint64_t (*)(const SphereBlock*, unsigned, const PrefilterRay&);

const Candidates kCandidates = cpuHasAvx2() ? sphereCandidatesAvx2 : sphereCandidatesSse2;

}  // namespace

std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray) {
    const std::uint64_t mask = kCandidates(blocks, count, ray);
    return count >= 64 ? mask : mask & ((std::uint64_t{1} << count) - 1);
}

}  // namespace dropscope
