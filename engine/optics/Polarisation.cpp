#include "optics/Polarisation.hpp"

#include "optics/OpticsTolerance.hpp"

#include <cmath>
#include <stdexcept>

namespace dropscope {

Eigen::Vector3d turnedReference(const Eigen::Vector3d& reference, const Direction& from, const Direction& to) {
    // Rodrigues' rotation with w = from x to (|w| = sin t) and c = cos t: v c + w x v + w (w.v) / (1 + c).
    const Eigen::Vector3d w = from.vector().cross(to.vector());
    const double c = from.dot(to);
    const Eigen::Vector3d turned = reference * c + w.cross(reference) + w * (w.dot(reference) / (1.0 + c));
    // Rounding: perpendicular to `to` and unit again.
    return (turned - turned.dot(to.vector()) * to.vector()).normalized();
}

namespace {

// The frame whose parallel axis is `direction` x s: the one frame every beam at an interface shares s with.
// s is perpendicular to the normal and to the incident direction, so to every beam there; the cross product
// is of unit length but for rounding, which normalising keeps from building up event after event.
Polarisation inPlaneFrame(const StokesVector& stokes, const Eigen::Vector3d& s, const Direction& direction) {
    return {stokes, direction.vector().cross(s).normalized()};
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

StokesVector throughDiagonalElement(const StokesVector& stokes, std::complex<double> parallel,
                                    std::complex<double> perpendicular, double power) {
    // docs/optics.md, (P4): from E_par' = a E_par, E_perp' = b E_perp and the definitions of I, Q, U, V.
    const double a2 = std::norm(parallel);
    const double b2 = std::norm(perpendicular);
    const std::complex<double> ab = parallel * std::conj(perpendicular);
    const double sum = 0.5 * power * (a2 + b2);
    const double difference = 0.5 * power * (a2 - b2);
    const double re = power * ab.real();
    const double im = power * ab.imag();
    return {sum * stokes[0] + difference * stokes[1], difference * stokes[0] + sum * stokes[1],
            re * stokes[2] + im * stokes[3], -im * stokes[2] + re * stokes[3]};
}

PlaneOfIncidence planeOfIncidence(const Polarisation& light, const Direction& incident, const Direction& normal) {
    const Eigen::Vector3d kCrossN = incident.vector().cross(normal.vector());
    const double sine = kCrossN.norm();
    const Eigen::Vector3d s = sine < tolerance::kNormalIncidenceSine ? perpendicularAxis(light.reference, incident)
                                                                     : Eigen::Vector3d(kCrossN / sine);
    return {s, stokesInFrame(light, incident, incident.vector().cross(s))};
}

double polarisedReflectance(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes) {
    return throughDiagonalElement(plane.stokes, amplitudes.rp, amplitudes.rs, 1.0)[0] / plane.stokes[0];
}

Polarisation reflectedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                   const Direction& reflected) {
    return inPlaneFrame(throughDiagonalElement(plane.stokes, amplitudes.rp, amplitudes.rs, 1.0), plane.s, reflected);
}

Polarisation transmittedPolarisation(const PlaneOfIncidence& plane, const FresnelAmplitudes& amplitudes,
                                     const Direction& transmitted) {
    return inPlaneFrame(throughDiagonalElement(plane.stokes, amplitudes.tp, amplitudes.ts, amplitudes.transmittedPower),
                        plane.s, transmitted);
}

}  // namespace dropscope
