#pragma once

#include "optics/Fresnel.hpp"
#include "scene/SceneLoader.hpp"
#include "transport/OpticalScene.hpp"

#include <cmath>
#include <string>

namespace dropscope::testing {

// A scene from JSON text (docs/scene-format.md) with the boilerplate filled in: unit mm, 532 nm,
// ambient "air" (n = 1 unless `media` redefines it).
inline Scene sceneFromJson(const std::string& media, const std::string& shapes, const std::string& sources) {
    const std::string text = R"({"dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air", "media": {)" +
                             media + R"(}, "shapes": [)" + shapes + R"(], "sources": [)" + sources + "]}";
    return parseScene(text, "test.json");
}

// Tolerance for a Monte Carlo fraction against its expectation p after n photons: five binomial
// standard deviations, so a correct tracer fails about once in 3.5 million runs (the seeds are fixed,
// so in practice never), while a physics error of a few tenths of a percent at 1e5 photons is caught.
inline double monteCarloTolerance(double p, double n) { return 5.0 * std::sqrt(std::max(p * (1.0 - p), 1.0 / n) / n); }

// The share of isotropic photons from a point at r0 radii from the centre of a sphere of index n (in
// a medium of index 1) that an event cap of `cap` ends. A ray at angle alpha to the radius meets the
// wall at sin(theta) = r0 sin(alpha) on every bounce, so it reflects `cap` times in a row with
// probability R(theta)^cap, and for ever (R = 1) past the critical angle. With `polarised` light s and p
// never mix (every bounce is in the plane of the ray and the centre), so it is (Rs^cap + Rp^cap)/2 of
// unpolarised light; without, the unpolarised model's ((Rs + Rp)/2)^cap. cos(alpha) is uniform;
// midpoint rule with 2e5 steps, far finer than the Monte Carlo noise it is compared with.
inline double capLossInsideSphere(double n, double r0, std::uint32_t cap, bool polarised) {
    constexpr int kSteps = 200000;
    double lost = 0.0;
    for (int step = 0; step < kSteps; ++step) {
        const double mu = -1.0 + 2.0 * (step + 0.5) / kSteps;
        const double sinTheta = r0 * std::sqrt(1 - mu * mu);
        const FresnelReflectance r = fresnelReflectance(std::sqrt(1 - sinTheta * sinTheta), n, 1.0);
        const double capped =
            polarised ? 0.5 * (std::pow(r.s, cap) + std::pow(r.p, cap)) : std::pow(r.unpolarised(), cap);
        lost += capped / kSteps;
    }
    return lost;
}

}  // namespace dropscope::testing
