#pragma once

#include <complex>

namespace dropscope {

// Power reflectances at an interface from real index n1 into n2, for the cosine of the angle of
// incidence (0 < cosIncidence <= 1). Past the critical angle every polarisation reflects fully.
struct FresnelReflectance {
    double s;  // perpendicular (TE) polarisation
    double p;  // parallel (TM) polarisation
    double unpolarised() const { return 0.5 * (s + p); }
};

// The exact Fresnel equations for real indices (Born and Wolf, Principles of Optics, 1.5; docs/optics.md).
FresnelReflectance fresnelReflectance(double cosIncidence, double n1, double n2);

// Schlick's approximation R0 + (1 - R0)(1 - cos)^5, with the cosine taken on the optically thinner
// side, for comparison only.
double schlickReflectance(double cosIncidence, double n1, double n2);

// The Fresnel amplitude coefficients (docs/optics.md, "Fresnel amplitudes"): the ratios of reflected and
// transmitted to incident field components, s perpendicular to the plane of incidence, p in it, each
// beam's p axis being k x s for its own direction k and the one s axis of the interface. Past the
// critical angle cos(theta_t) is i sqrt(sin^2 theta_t - 1) (an evanescent wave decaying into n2 for
// the exp(-i omega t) convention), |rs| = |rp| = 1, and nothing is transmitted.
struct FresnelAmplitudes {
    std::complex<double> rs, rp;    // reflection
    double ts = 0.0, tp = 0.0;      // transmission (0 past the critical angle)
    double transmittedPower = 0.0;  // n2 cos(theta_t) / (n1 cos(theta_i)): power per |t|^2; 0 past it
    bool totalInternalReflection = false;
};

FresnelAmplitudes fresnelAmplitudes(double cosIncidence, double n1, double n2);
// The same with the caller's verdict on total reflection (eq. 4.7's, so that a ray at the critical angle
// to rounding is not total by one test and transmitted by the other): cos(theta_t) is clamped to 0 on
// the side the verdict says.
FresnelAmplitudes fresnelAmplitudes(double cosIncidence, double n1, double n2, bool totalReflection);

}  // namespace dropscope
