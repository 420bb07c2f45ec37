#include "transport/PolarisedCrossing.hpp"

#include <stdexcept>

namespace dropscope {

PolarisedCrossing::PolarisedCrossing(const Polarisation& light, const SurfaceCrossing& crossing)
    : incident_(crossing.incident),
      normal_(crossing.normal),
      transmittedDirection_(crossing.transmitted),
      plane_(planeOfIncidence(light, crossing.incident, crossing.normal)),
      amplitudes_(fresnelAmplitudes(crossing.cosIncidence, crossing.n1, crossing.n2, crossing.totalInternalReflection)),
      reflectance_(crossing.totalInternalReflection ? 1.0 : polarisedReflectance(plane_, amplitudes_)) {}

Polarisation PolarisedCrossing::reflected() const {
    return reflectedPolarisation(plane_, amplitudes_, reflect(incident_, normal_));
}

Polarisation PolarisedCrossing::transmitted() const {
    return transmittedPolarisation(plane_, amplitudes_, transmittedDirection_);
}

Polarisation withUnitPower(Polarisation light) {
    // A branch is chosen with the probability of its power, which is then > 0.
    if (!(light.stokes[0] > 0.0)) throw std::logic_error("withUnitPower: a branch of no power was chosen");
    light.stokes /= light.stokes[0];
    return light;
}

}  // namespace dropscope
