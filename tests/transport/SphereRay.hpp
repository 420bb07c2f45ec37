#pragma once

// One ray through a homogeneous sphere of relative index m > 1, with the s and p polarisations apart: the
// formulae of the reference in SphereRayOptics.hpp (docs/validation.md, "Ray optics of a sphere with s and p
// tracked"). Plain C++, nothing from engine/: the Fresnel formulae are derived and written out again here.
// Angles in radians unless named in degrees.

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope::testing {

// Power reflectances of the surface of a sphere of relative index m > 1 for a ray meeting it from outside
// with cos(theta_i) = cosIncidence (Born and Wolf, Principles of Optics, 1.5). A ray inside meets the
// surface at the refraction angle theta_t and reflects the same fractions (Stokes relations, r' = -r),
// and a lossless interface transmits T = 1 - R.
struct PolarisedReflectance {
    double s;  // polarised perpendicular to the plane of incidence (TE)
    double p;  // polarised in the plane of incidence (TM)
    double mean() const { return 0.5 * (s + p); }
};

// cos(theta_t) from Snell's law sin(theta_i) = m sin(theta_t), written as (m^2 - 1 + cos^2 theta_i) / m^2
// so that it keeps its accuracy at grazing incidence and for m close to 1.
inline double cosRefraction(double cosIncidence, double m) {
    return std::sqrt((m - 1.0) * (m + 1.0) + cosIncidence * cosIncidence) / m;
}

inline PolarisedReflectance sphereSurfaceReflectance(double cosIncidence, double m) {
    const double cosT = cosRefraction(cosIncidence, m);
    const double amplitudeS = (cosIncidence - m * cosT) / (cosIncidence + m * cosT);
    const double amplitudeP = (m * cosIncidence - cosT) / (m * cosIncidence + cosT);
    return {amplitudeS * amplitudeS, amplitudeP * amplitudeP};
}

// The fraction of one polarisation's power that leaves in ray order p (p - 1 internal reflections, p chords
// of transmission tau each): R for p = 0, (1 - R)^2 R^(p-1) tau^p for p >= 1.
inline double rayOrderShare(double reflectance, double chordTransmission, int order) {
    if (order == 0) return reflectance;
    const double transmittance = 1.0 - reflectance;
    return transmittance * transmittance * std::pow(reflectance, order - 1) * std::pow(chordTransmission, order);
}

// Deviation of ray order p: pi - 2 theta_i for p = 0, 2 (theta_i - theta_t) + (p - 1)(pi - 2 theta_t) else.
inline double rayOrderDeviation(double thetaI, double thetaT, int order) {
    constexpr double pi = std::numbers::pi;
    if (order == 0) return pi - 2.0 * thetaI;
    return 2.0 * (thetaI - thetaT) + (order - 1) * (pi - 2.0 * thetaT);
}

// A deviation folded into the scattering angle, in [0, pi] (0 = forward).
inline double scatteringAngle(double deviation) {
    constexpr double pi = std::numbers::pi;
    const double turn = std::fmod(deviation, 2.0 * pi);
    return turn <= pi ? turn : 2.0 * pi - turn;
}

// The ray of minimum deviation of order p >= 2 (Descartes): cos^2 theta_i = (m^2 - 1) / (p^2 - 1), which
// exists for m < p.
struct DescartesRay {
    double incidenceDegrees;
    double scatteringAngleDegrees;
    double degreeOfPolarisation;  // -Q/I = (P_s - P_p) / (P_s + P_p): > 0 when polarised across the scattering plane
};

inline DescartesRay descartesRay(double m, int order) {
    if (order < 2 || !(m > 1.0) || m >= order) throw std::invalid_argument("descartesRay: no minimum deviation");
    const double cosI = std::sqrt((m * m - 1.0) / (order * order - 1.0));
    const double thetaI = std::acos(cosI);
    const double thetaT = std::atan2(std::sin(thetaI) / m, cosRefraction(cosI, m));
    const PolarisedReflectance r = sphereSurfaceReflectance(cosI, m);
    const double shareS = rayOrderShare(r.s, 1.0, order);
    const double shareP = rayOrderShare(r.p, 1.0, order);
    constexpr double degrees = 180.0 / std::numbers::pi;
    return {thetaI * degrees, scatteringAngle(rayOrderDeviation(thetaI, thetaT, order)) * degrees,
            (shareS - shareP) / (shareS + shareP)};
}

// Power leaving into some set of directions, as fractions of the power incident on the sphere.
struct PowerFraction {
    double s = 0.0;                   // of the incident s-polarised power (s stays s at every interface of a ray)
    double p = 0.0;                   // of the incident p-polarised power: polarised in the scattering plane
    double unpolarisedFresnel = 0.0;  // with R = (R_s + R_p)/2 at every interface: a tracer without polarisation

    double intensity() const { return 0.5 * (s + p); }  // I, for unpolarised light in
    double q() const { return 0.5 * (p - s); }          // Q = I_parallel - I_perpendicular (scattering plane)
    double degreeOfPolarisation() const { return -q() / intensity(); }  // -P12/P11
    PowerFraction& operator+=(const PowerFraction& other) {
        s += other.s;
        p += other.p;
        unpolarisedFresnel += other.unpolarisedFresnel;
        return *this;
    }
};

}  // namespace dropscope::testing
