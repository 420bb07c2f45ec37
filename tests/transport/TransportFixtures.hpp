#pragma once

#include "scene/SceneLoader.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/TraceRun.hpp"

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
inline double monteCarloTolerance(double p, double n) {
    return 5.0 * std::sqrt(std::max(p * (1.0 - p), 1.0 / n) / n);
}

inline double fraction(std::uint64_t count, const TraceTally& tally) {
    return static_cast<double>(count) / static_cast<double>(tally.photons);
}

}  // namespace dropscope::testing
