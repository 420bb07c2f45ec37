#include "render/Colour.hpp"

#include <algorithm>
#include <cmath>

namespace dropscope::render {

Colour mediumColour(std::size_t index) {
    static constexpr std::array<Colour, 8> kPalette{{
        {0.62f, 0.80f, 1.00f, 1.0f},  // 0: usually the ambient (not drawn)
        {0.25f, 0.55f, 0.95f, 1.0f},
        {0.35f, 0.80f, 0.55f, 1.0f},
        {0.95f, 0.60f, 0.25f, 1.0f},
        {0.80f, 0.40f, 0.80f, 1.0f},
        {0.90f, 0.85f, 0.30f, 1.0f},
        {0.55f, 0.55f, 0.55f, 1.0f},
        {0.90f, 0.35f, 0.35f, 1.0f},
    }};
    return kPalette[index % kPalette.size()];
}

Colour levelColour(int level) {
    static constexpr std::array<Colour, 6> kLevels{{
        {1.00f, 1.00f, 1.00f, 1.0f},
        {1.00f, 0.80f, 0.20f, 1.0f},
        {0.30f, 0.90f, 0.40f, 1.0f},
        {0.30f, 0.70f, 1.00f, 1.0f},
        {0.90f, 0.40f, 0.90f, 1.0f},
        {1.00f, 0.45f, 0.35f, 1.0f},
    }};
    return kLevels[static_cast<std::size_t>(std::max(level, 0)) % kLevels.size()];
}

Colour viridis(double t) {
    // viridis at t = 0, 1/8, ..., 1 (the nine-step table of matplotlib's and R's viridis), linearly
    // interpolated.
    static constexpr std::array<std::array<float, 3>, 9> kSamples{{
        {0.2667f, 0.0039f, 0.3294f},  // #440154
        {0.2784f, 0.1765f, 0.4824f},  // #472D7B
        {0.2314f, 0.3216f, 0.5451f},  // #3B528B
        {0.1725f, 0.4471f, 0.5569f},  // #2C728E
        {0.1294f, 0.5647f, 0.5490f},  // #21908C
        {0.1529f, 0.6784f, 0.5059f},  // #27AD81
        {0.3647f, 0.7843f, 0.3882f},  // #5DC863
        {0.6667f, 0.8627f, 0.1961f},  // #AADC32
        {0.9922f, 0.9059f, 0.1451f},  // #FDE725
    }};
    const double x = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 8.0;
    const auto i = std::min(static_cast<std::size_t>(x), std::size_t{7});
    const auto f = static_cast<float>(x - static_cast<double>(i));
    Colour c{0, 0, 0, 1};
    for (std::size_t k = 0; k < 3; ++k) c[k] = kSamples[i][k] + f * (kSamples[i + 1][k] - kSamples[i][k]);
    return c;
}

Colour logWeightColour(double weight, double decades) {
    if (!(weight > 0.0)) return viridis(0.0);
    return viridis(1.0 + std::log10(weight) / decades);
}

Colour eventColour(EventType type) {
    switch (type) {
    case EventType::Emit: return {1.00f, 1.00f, 1.00f, 1.0f};       // white
    case EventType::Reflect: return {1.00f, 0.55f, 0.10f, 1.0f};    // orange
    case EventType::Refract: return {0.20f, 0.75f, 1.00f, 1.0f};    // sky blue
    case EventType::Tir: return {0.85f, 0.30f, 1.00f, 1.0f};        // violet
    case EventType::Absorb: return {0.90f, 0.15f, 0.15f, 1.0f};     // red
    case EventType::Escape: return {0.35f, 0.90f, 0.35f, 1.0f};     // green
    case EventType::Lost: return {1.00f, 0.20f, 0.75f, 1.0f};       // pink
    case EventType::Detect: return {1.00f, 0.85f, 0.10f, 1.0f};     // yellow
    case EventType::Truncated: return {0.55f, 0.55f, 0.55f, 1.0f};  // grey
    case EventType::Diffract: return {0.30f, 0.95f, 0.95f, 1.0f};   // cyan
    }
    return {1.0f, 1.0f, 1.0f, 1.0f};
}

}  // namespace dropscope::render
