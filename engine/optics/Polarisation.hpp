#pragma once

#include "geometry/Vector.hpp"
#include "optics/Fresnel.hpp"
#include "optics/Stokes.hpp"

#include <complex>

namespace dropscope {

// The polarisation of a beam or a photon (docs/optics.md, "Polarisation"): its Stokes vector in the frame
// whose parallel axis is `reference`, a unit vector perpendicular to the direction of travel k. The
// frame's perpendicular axis is reference x k, so that (perpendicular, parallel, k) is right-handed, as
// Bohren and Huffman's (e_perp, e_par, e_r) are.
struct Polarisation {
    StokesVector stokes = unpolarisedStokes();
    Eigen::Vector3d reference = Eigen::Vector3d::UnitX();
};

// The perpendicular axis of the frame with parallel axis `reference` for light along `direction`.
inline Eigen::Vector3d perpendicularAxis(const Eigen::Vector3d& reference, const Direction& direction) {
    return reference.cross(direction.vector());
}

// The parallel axis of light turned from `from` to `to` without a change of its state (diffraction): `reference`
// turned by the rotation about from x to that takes `from` to `to`. `to` must not be -from.
Eigen::Vector3d turnedReference(const Eigen::Vector3d& reference, const Direction& from, const Direction& to);

// The Stokes vector of the same light in the frame whose parallel axis is `newReference` (unit, also
// perpendicular to `direction`): I and V are unchanged, (Q, U) turn by twice the angle between the axes.
StokesVector stokesInFrame(const Polarisation& light, const Direction& direction, const Eigen::Vector3d& newReference);

// M S, with M the Mueller matrix of an element that multiplies a beam's parallel field component by
// `parallel` and its perpendicular one by `perpendicular` (a diagonal Jones matrix), times `power`
// (docs/optics.md, (P4)).
StokesVector throughDiagonalElement(const StokesVector& stokes, std::complex<double> parallel,
                                    std::complex<double> perpendicular, double power);

// A beam arriving at an interface along `incident`, described in the plane of incidence: `s` its unit
// normal (k x N), and the Stokes vector in the frame with parallel axis p = k x s. At normal incidence,
// where k x N vanishes, s is the beam's own perpendicular axis (tolerance::kNormalIncidenceSine).
struct PlaneOfIncidence {
    Eigen::Vector3d s;
    StokesVector stokes;
};

PlaneOfIncidence planeOfIncidence(const Polarisation& light, const Direction& incident, const Direction& normal);

// The share of the beam's power reflected, (M_R S)_0 / S_0, with M_R the diagonal element of (rp, rs).
double polarisedReflectance(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes);

// The reflected and the transmitted light, M_R S and M_T S (not renormalised: I is the power each
// carries), each in the frame whose parallel axis is its own direction x s.
Polarisation reflectedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                   const Direction& reflected);
Polarisation transmittedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                     const Direction& transmitted);

}  // namespace dropscope
