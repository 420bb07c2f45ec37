#pragma once

#include "optics/Fresnel.hpp"
#include "optics/Polarisation.hpp"
#include "transport/SurfaceCrossing.hpp"

namespace dropscope {

// The polarisation side of a surface crossing (docs/transport.md, "Polarised photons"): the light's
// Stokes vector in the plane of incidence and the Fresnel amplitudes there, with total internal
// reflection decided as the crossing decided it.
class PolarisedCrossing {
public:
    PolarisedCrossing(const Polarisation& light, const SurfaceCrossing& crossing);

    // The share of this light's power reflected, (M_R S)_0 / S_0; 1 under total internal reflection.
    double reflectance() const { return reflectance_; }
    // M_R S and M_T S in the reflected and transmitted beams' frames, I the power each carries.
    Polarisation reflected() const;
    Polarisation transmitted() const;

private:
    Direction incident_;
    Direction normal_;
    Direction transmittedDirection_;
    PlaneOfIncidence plane_;
    FresnelAmplitudes amplitudes_;
    double reflectance_;
};

// `light` scaled to I = 1: a Monte Carlo photon's Stokes vector after it has chosen a branch with the
// probability of that branch's power (the estimator stays unbiased). Throws std::logic_error for I <= 0.
Polarisation withUnitPower(Polarisation light);

}  // namespace dropscope
