#pragma once

#include <Eigen/Core>

#include <cmath>

namespace dropscope {

// The Stokes vector (I, Q, U, V) of Bohren and Huffman (1983, sect. 2.11), docs/optics.md "Polarisation":
// with E_par and E_perp the field's components along a frame's parallel and perpendicular axes,
//   I = |E_par|^2 + |E_perp|^2,  Q = |E_par|^2 - |E_perp|^2,
//   U = 2 Re(E_par E_perp*),     V = -2 Im(E_par E_perp*)       (time dependence exp(-i omega t)).
// I is a beam's power; Q > 0 means polarised along the parallel axis; V > 0 right-handed.
using StokesVector = Eigen::Vector4d;

inline StokesVector unpolarisedStokes(double power = 1.0) { return {power, 0.0, 0.0, 0.0}; }

// sqrt(Q^2 + U^2) / I, 0 for a beam of no power.
inline double degreeOfLinearPolarisation(const StokesVector& s) {
    return s[0] > 0.0 ? std::hypot(s[1], s[2]) / s[0] : 0.0;
}

// sqrt(Q^2 + U^2 + V^2) / I, 0 for a beam of no power.
inline double degreeOfPolarisation(const StokesVector& s) {
    return s[0] > 0.0 ? std::sqrt(s[1] * s[1] + s[2] * s[2] + s[3] * s[3]) / s[0] : 0.0;
}

}  // namespace dropscope
