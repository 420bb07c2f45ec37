#pragma once

#include <cmath>
#include <numbers>

namespace dropscope::validation {

// The caustic of the rays that leave a sphere of relative index n after k internal reflections:
// D = 2(θi − θt) + k(π − 2θt) is least where cos² θi = (n² − 1)/(k(k + 2)) (Descartes). The rays pile up
// on the side of larger D.
struct Caustic {
    double scatteringDeg;  // D folded into [0, 180]
    bool brightAbove;      // the bright side is at larger scattering angles
};

inline Caustic descartes(double n, int k) {
    const double thetaI = std::acos(std::sqrt((n * n - 1) / (k * (k + 2))));
    const double thetaT = std::asin(std::sin(thetaI) / n);
    const double deviation = 2 * (thetaI - thetaT) + k * (std::numbers::pi - 2 * thetaT);
    return {std::acos(std::cos(deviation)) * 180.0 / std::numbers::pi, std::sin(deviation) > 0};
}

}  // namespace dropscope::validation
