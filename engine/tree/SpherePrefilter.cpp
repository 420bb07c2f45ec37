// The conservative single-precision sphere test the octree runs before the exact double one
// (docs/octree.md, "The sphere prefilter"). SSE2 is the x86-64 baseline; the AVX2 variant is chosen at
// run time, so the binary stays portable. Only the candidate mask is computed here: the exact
// distanceToSurface runs in baseline code, so its doubles never depend on the CPU.
#include "tree/SpherePrefilter.hpp"

#include <immintrin.h>
#include <cmath>
#include <limits>

namespace dropscope {

void SphereBlock::pack(unsigned lane, const SphereGeometry& sphere, const Point& cellCentre) {
    float* axes[3] = {x, y, z};
    double moved = 0.0;  // squared distance the rounding moved the centre
    bool finite = true;
    for (int axis = 0; axis < 3; ++axis) {
        const double relative = sphere.center[axis] - cellCentre[axis];
        const auto rounded = static_cast<float>(relative);
        axes[axis][lane] = rounded;
        const double error = static_cast<double>(rounded) - relative;
        moved += error * error;
        finite = finite && std::isfinite(rounded);
    }
    const double needed = sphere.radius + 2.0 * sphere.band + std::sqrt(moved);
    auto radiusUp = static_cast<float>(needed);
    if (static_cast<double>(radiusUp) < needed)
        radiusUp = std::nextafter(radiusUp, std::numeric_limits<float>::infinity());
    radius[lane] = radiusUp;
    if (!finite || !std::isfinite(radiusUp)) {
        // Beyond float range: an infinite ball every ray meets, so the exact test decides.
        x[lane] = y[lane] = z[lane] = 0.0f;
        radius[lane] = std::numeric_limits<float>::infinity();
    }
}

void SphereBlock::clear(unsigned lane) {
    x[lane] = y[lane] = z[lane] = std::numeric_limits<float>::quiet_NaN();
    radius[lane] = 0.0f;
}

namespace {

// With O = centre - origin, b = O.d (distance along the ray to the centre's foot) and w = O - b d (the
// perpendicular, cancellation-free), a sphere stays a candidate when |w| <= r + slack, b >= -(r + slack)
// and b - (r + slack) <= limit. NaN (unused lanes) fails every comparison.
struct Sse2Lanes {
    __m128d ox, oy, oz, dx, dy, dz, slack, limit;

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
        const __m128d reach = _mm_add_pd(r, slack);
        __m128d ok = _mm_cmple_pd(perpendicular2, _mm_mul_pd(reach, reach));
        ok = _mm_and_pd(ok, _mm_cmpge_pd(_mm_add_pd(b, reach), _mm_setzero_pd()));
        ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_sub_pd(b, reach), limit));
        return _mm_movemask_pd(ok);
    }
};

std::uint64_t candidatesSse2(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray) {
    const Sse2Lanes lanes{_mm_set1_pd(ray.origin[0]),    _mm_set1_pd(ray.origin[1]),    _mm_set1_pd(ray.origin[2]),
                          _mm_set1_pd(ray.direction[0]), _mm_set1_pd(ray.direction[1]), _mm_set1_pd(ray.direction[2]),
                          _mm_set1_pd(ray.slack),        _mm_set1_pd(ray.limit)};
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += SphereBlock::kWidth) {
        const SphereBlock& block = blocks[first / SphereBlock::kWidth];
        const __m128 x = _mm_load_ps(block.x);
        const __m128 y = _mm_load_ps(block.y);
        const __m128 z = _mm_load_ps(block.z);
        const __m128 r = _mm_load_ps(block.radius);
        const int low = lanes.accept(_mm_cvtps_pd(x), _mm_cvtps_pd(y), _mm_cvtps_pd(z), _mm_cvtps_pd(r));
        const int high = lanes.accept(_mm_cvtps_pd(_mm_movehl_ps(x, x)), _mm_cvtps_pd(_mm_movehl_ps(y, y)),
                                      _mm_cvtps_pd(_mm_movehl_ps(z, z)), _mm_cvtps_pd(_mm_movehl_ps(r, r)));
        mask |= static_cast<std::uint64_t>(low | high << 2) << first;
    }
    return mask;
}

__attribute__((target("avx2,fma"))) std::uint64_t candidatesAvx2(const SphereBlock* blocks, unsigned count,
                                                                 const PrefilterRay& ray) {
    const __m256d ox = _mm256_set1_pd(ray.origin[0]);
    const __m256d oy = _mm256_set1_pd(ray.origin[1]);
    const __m256d oz = _mm256_set1_pd(ray.origin[2]);
    const __m256d dx = _mm256_set1_pd(ray.direction[0]);
    const __m256d dy = _mm256_set1_pd(ray.direction[1]);
    const __m256d dz = _mm256_set1_pd(ray.direction[2]);
    const __m256d slack = _mm256_set1_pd(ray.slack);
    const __m256d limit = _mm256_set1_pd(ray.limit);
    std::uint64_t mask = 0;
    for (unsigned first = 0; first < count; first += SphereBlock::kWidth) {
        const SphereBlock& block = blocks[first / SphereBlock::kWidth];
        const __m256d x = _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(block.x)), ox);
        const __m256d y = _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(block.y)), oy);
        const __m256d z = _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(block.z)), oz);
        const __m256d reach = _mm256_add_pd(_mm256_cvtps_pd(_mm_load_ps(block.radius)), slack);
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

using Candidates = std::uint64_t (*)(const SphereBlock*, unsigned, const PrefilterRay&);

const Candidates kCandidates = [] {
    __builtin_cpu_init();  // required before __builtin_cpu_supports in a static initialiser
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? candidatesAvx2 : candidatesSse2;
}();

}  // namespace

std::uint64_t sphereCandidates(const SphereBlock* blocks, unsigned count, const PrefilterRay& ray) {
    const std::uint64_t mask = kCandidates(blocks, count, ray);
    return count >= 64 ? mask : mask & ((std::uint64_t{1} << count) - 1);
}

}  // namespace dropscope
