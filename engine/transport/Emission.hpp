#pragma once

#include "geometry/Vector.hpp"
#include "optics/Polarisation.hpp"
#include "scene/Source.hpp"
#include "transport/PhotonRandom.hpp"

namespace dropscope {

struct Ray {
    Point origin;
    Direction direction;
};

// One photon leaving `source` (docs/transport.md, "Sources"): beam, uniform over its disk (r = R sqrt(u),
// phi = 2 pi u'); ray, the pencil itself (no random numbers drawn); point, isotropic
// (cos theta = 1 - 2u, phi = 2 pi u').
Ray emitPhoton(const Source& source, PhotonRandom& random);

// A direction uniform over the cone of half-angle `halfAngleDeg` around `axis` (docs/spectra.md, "The
// divergence cone"): cos theta = 1 - u (1 - cos alpha), phi = 2 pi u', with 1 - cos written 2 sin^2(x/2)
// so that the sun's 0.27 degrees keeps full precision. Draws two numbers from `random`.
Direction directionInCone(const Direction& axis, double halfAngleDeg, PhotonRandom& random);

// What a photon of `source` carries from its source stream (PhotonRandom::kSourceStream): its wavelength,
// drawn from `spectrum` (no number drawn for a single line), and its direction, within the source's
// divergence cone around source.direction (no numbers drawn without a divergence).
struct EmittedLight {
    double wavelengthNm = 0.0;
    Direction direction;
};
EmittedLight emitLight(const Source& source, const Spectrum& spectrum, PhotonRandom& sourceRandom);

// The polarisation of a photon leaving `source` along `direction`, with I = 1: the source's state in its
// reference frame (made exactly perpendicular to `direction`), or unpolarised light in the frame
// unpolarisedLight gives. Draws no random numbers. Throws std::invalid_argument for a reference that is not
// finite or lies along `direction` (checkPolarisation refuses those sources first).
Polarisation emittedPolarisation(const Source& source, const Direction& direction);

// Unpolarised light of unit power along `direction`, its reference the u of perpendicularBasis.
Polarisation unpolarisedLight(const Direction& direction);

// Two unit vectors that make (u, v, d) a right-handed orthonormal basis.
void perpendicularBasis(const Direction& d, Eigen::Vector3d& u, Eigen::Vector3d& v);

}  // namespace dropscope
