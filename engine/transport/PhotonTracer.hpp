#pragma once

#include "transport/DropletDiffraction.hpp"
#include "transport/Emission.hpp"
#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/PhotonObserver.hpp"
#include "transport/PhotonRandom.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <cstdint>
#include <optional>
#include <string_view>

namespace dropscope {

struct TransportSettings {
    // Interface events (reflect, refract, tir, tangent passes) one photon may have before it is
    // counted lost with LostReason::EventCap. docs/transport.md explains the default.
    std::uint32_t maxEvents = 10000;
    FresnelModel fresnel = FresnelModel::Exact;
    // Stokes needs FresnelModel::Exact; with None every photon reflects with the unpolarised R.
    PolarisationModel polarisation = PolarisationModel::Stokes;
    DiffractionModel diffraction = DiffractionModel::None;
};

enum class PhotonFate { Escaped, Absorbed, Lost, Detected };

// "escaped", "absorbed", "lost", "detected": as paths.jsonl and the app write it.
std::string_view photonFateName(PhotonFate fate);

struct PhotonOutcome {
    PhotonFate fate = PhotonFate::Lost;
    LostReason lostReason = LostReason::EventCap;  // when fate == Lost
    Direction finalDirection;                      // the escape direction when fate == Escaped
    bool metSurface = false;                       // false: it never reached any surface
    EventCounts events;
};

// One analog Monte Carlo photon (docs/transport.md): free flight to the next surface through the
// octree; in an absorbing medium an exponential absorption distance is drawn first; at a surface it
// reflects with probability R (always on total internal reflection), else refracts. With
// PolarisationModel::Stokes the photon carries `polarisation` (unpolarisedLight when absent), R is that of
// its Stokes vector, and the Stokes vector of the branch taken is renormalised to I = 1. The photon's vacuum
// wavelength is `wavelengthNm` (the scene's when absent): every interface uses the media's n and every
// flight their absorption at it. Observers measure scattering angles from `axis` (PhotonState::axis: the
// axis of a divergent beam; the emitted direction when absent). An `observer` is told every event, starting
// with the emission, and (if it wants them) every flight between them. A photon that crosses an absorbing
// plane detector (on a side it counts) ends there: a Detect event, fate Detected. With DiffractionModel::Fraunhofer
// (the scene built with haloes), a photon that passes through the halo of a sphere or an ellipsoid but misses the
// droplet is turned by an angle drawn from the Airy pattern of the droplet's outline, at the middle of its chord
// through the halo (a Diffract event); ray optics is unchanged for photons that meet the droplet. The halo's ring
// is as large as the outline: of the photons of a plane wave that meet a droplet's extinction cross-section (twice
// its outline), half are diffracted.
PhotonOutcome tracePhoton(const OpticalScene& scene, const Ray& emitted, PhotonRandom& random,
                          const TransportSettings& settings, PhotonObserver* observer = nullptr,
                          const std::optional<Polarisation>& polarisation = std::nullopt,
                          std::optional<double> wavelengthNm = std::nullopt,
                          const std::optional<Direction>& axis = std::nullopt);

}  // namespace dropscope
