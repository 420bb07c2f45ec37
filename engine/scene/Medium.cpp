#include "scene/Medium.hpp"

#include <numbers>

namespace dropscope {

double absorptionFromExtinction(double kappa, double wavelengthInSceneUnits) {
    return 4.0 * std::numbers::pi * kappa / wavelengthInSceneUnits;  // seed eq. 3.13
}

}  // namespace dropscope
