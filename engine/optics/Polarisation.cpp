#include "optics/Polarisation.hpp"

#include "optics/OpticsTolerance.hpp"

#include <cmath>
#include <stdexcept>

namespace dropscope {

namespace {

// `axis` made exactly perpendicular to `direction` and of unit length.
Eigen::Vector3d perpendicularUnit(const Eigen::Vector3d& axis, const Direction& direction) {
    return (axis - axis.dot(direction.vector()) * direction.vector()).normalized();
}

// The frame whose parallel axis is `direction` x s: the one frame every beam at an interface shares s with.
Polarisation inPlaneFrame(const StokesVector& stokes, const Eigen::Vector3d& s, const Direction& direction) {
    return {stokes, perpendicularUnit(direction.vector().cross(s), direction)};
}

}  // namespace

StokesVector stokesInFrame(const Polarisation& light, const Direction& direction, const Eigen::Vector3d& newReference) {
    // newReference = c e_par - t e_perp for the rotation by psi about k (c = cos psi, t = sin psi); then
    // Q' = cos 2psi Q - sin 2psi U, U' = sin 2psi Q + cos 2psi U (docs/optics.md, (P3)).
    const double c = newReference.dot(light.reference);
    const double t = -newReference.dot(perpendicularAxis(light.reference, direction));
    const double norm = c * c + t * t;
    if (!(norm > 0.0)) throw std::logic_error("stokesInFrame: the new reference is not perpendicular to the beam");
    const double cos2 = (c * c - t * t) / norm;
    const double sin2 = 2.0 * c * t / norm;
    const StokesVector& s = light.stokes;
    return {s[0], cos2 * s[1] - sin2 * s[2], sin2 * s[1] + cos2 * s[2], s[3]};
}

MuellerMatrix diagonalMueller(std::complex<double> parallel, std::complex<double> perpendicular, double power) {
    // docs/optics.md, (P4): from E_par' = a E_par, E_perp' = b E_perp and the definitions of I, Q, U, V.
    const double a2 = std::norm(parallel);
    const double b2 = std::norm(perpendicular);
    const std::complex<double> ab = parallel * std::conj(perpendicular);
    MuellerMatrix m;
    m << 0.5 * (a2 + b2), 0.5 * (a2 - b2), 0.0, 0.0,  //
        0.5 * (a2 - b2), 0.5 * (a2 + b2), 0.0, 0.0,   //
        0.0, 0.0, ab.real(), ab.imag(),               //
        0.0, 0.0, -ab.imag(), ab.real();
    return power * m;
}

PlaneOfIncidence planeOfIncidence(const Polarisation& light, const Direction& incident, const Direction& normal) {
    Eigen::Vector3d s = incident.vector().cross(normal.vector());
    if (s.norm() < tolerance::kNormalIncidenceSine) s = perpendicularAxis(light.reference, incident);
    s = perpendicularUnit(s, incident);
    return {s, stokesInFrame(light, incident, incident.vector().cross(s))};
}

double polarisedReflectance(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes) {
    const double rs2 = std::norm(amplitudes.rs);
    const double rp2 = std::norm(amplitudes.rp);
    const StokesVector& s = plane.stokes;
    return (0.5 * (rp2 + rs2) * s[0] + 0.5 * (rp2 - rs2) * s[1]) / s[0];
}

Polarisation reflectedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                   const Direction& reflected) {
    return inPlaneFrame(diagonalMueller(amplitudes.rp, amplitudes.rs, 1.0) * plane.stokes, plane.s, reflected);
}

Polarisation transmittedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                     const Direction& transmitted) {
    const MuellerMatrix m = diagonalMueller(amplitudes.tp, amplitudes.ts, amplitudes.transmittedPower);
    return inPlaneFrame(m * plane.stokes, plane.s, transmitted);
}

}  // namespace dropscope
