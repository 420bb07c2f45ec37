#pragma once

// The tolerances of the polarisation geometry, in one place (docs/optics.md, "Polarisation").
namespace dropscope::tolerance {

// Below this sine of the angle of incidence the plane of incidence is taken to hold the beam's own
// parallel axis instead of k x N. There the Fresnel amplitudes differ from their normal-incidence values
// by O(sin^2) ~ 1e-18, below double precision, so the plane's orientation cannot matter, while the
// direction of a cross product of that length (rounding ~1e-16 absolute) would be noise.
inline constexpr double kNormalIncidenceSine = 1e-9;

// The same for the scattering plane of an escaping photon (the plane of its emission and escape
// directions): below this sine of the scattering angle the photon's own frame is kept.
inline constexpr double kScatteringPlaneSine = 1e-9;

// A polarisation "reference" axis given in a scene must be perpendicular to its source's direction
// within this cosine (0.2 arc seconds): a reference meant to be perpendicular but written with 7 or more
// significant digits passes, a wrong axis is refused. It is then made exactly perpendicular.
inline constexpr double kReferencePerpendicularCosine = 1e-6;

// Q^2 + U^2 + V^2 <= I^2 of a Stokes vector given in a scene is checked with this relative slack, so a
// fully polarised state written in decimal (e.g. [1, 0.6, 0.8, 0]) is accepted; it is then scaled onto
// the sphere if it lies just outside.
inline constexpr double kStokesDegreeSlack = 1e-12;

}  // namespace dropscope::tolerance
