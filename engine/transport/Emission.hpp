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
