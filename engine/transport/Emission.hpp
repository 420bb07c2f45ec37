#pragma once

#include "geometry/Vector.hpp"
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

// Two unit vectors that make (u, v, d) a right-handed orthonormal basis.
void perpendicularBasis(const Direction& d, Eigen::Vector3d& u, Eigen::Vector3d& v);

}  // namespace dropscope
