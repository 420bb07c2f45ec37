#pragma once

#include "geometry/Vector.hpp"

#include <cmath>
#include <numbers>

namespace dropscope {

// Fraunhofer diffraction by the projected disk or ellipse of a droplet (docs/transport.md, "Diffraction").
// The Airy pattern of a disk of radius a at wavenumber k is I ~ (2 J1(u) / u)^2 with u = k a sin(theta). Over
// the plane of transverse wave vectors it is isotropic, and its radius u has the density 2 J1(u)^2 / u, whose
// integral is Rayleigh's encircled energy F(u) = 1 - J0(u)^2 - J1(u)^2 (Born & Wolf, 8.5.2).
double airyEncircledEnergy(double u);

// The u >= 0 with airyEncircledEnergy(u) = p, for 0 <= p < 1.
double airyRadiusQuantile(double p);

// An aperture seen along a direction: an ellipse with semi-axes `a` along the unit vector `e1` and `b` along
// `e2` (both perpendicular to the direction and to each other), in the length unit of the wavenumber.
struct ProjectedEllipse {
    double a = 0.0;
    double b = 0.0;
    Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
    Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
};

// The direction of a photon travelling along `direction` after Fraunhofer diffraction by `aperture` at
// `wavenumber` (2 pi n / lambda): the transverse wave vector is drawn from the aperture's Airy pattern (the
// disk's, stretched along the ellipse's axes), without the obliquity factor, and kept within sin(theta) <= 1.
// `uniform()` returns numbers in [0, 1); each try takes two of them (a sphere never needs a second try).
template <class Uniform>
Direction diffractedDirection(const Direction& direction, const ProjectedEllipse& aperture, double wavenumber,
                              Uniform&& uniform) {
    const double ka = wavenumber * aperture.a;
    const double kb = wavenumber * aperture.b;
    const double kept = airyEncircledEnergy(std::max(ka, kb));
    for (;;) {
        const double u = airyRadiusQuantile(kept * uniform());
        const double phi = 2.0 * std::numbers::pi * uniform();
        const double s1 = u * std::cos(phi) / ka;
        const double s2 = u * std::sin(phi) / kb;
        const double sine2 = s1 * s1 + s2 * s2;
        if (sine2 > 1.0) continue;
        return Direction(s1 * aperture.e1 + s2 * aperture.e2 + std::sqrt(1.0 - sine2) * direction.vector());
    }
}

}  // namespace dropscope
