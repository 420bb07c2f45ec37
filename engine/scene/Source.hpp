#pragma once

#include "geometry/Vector.hpp"
#include "optics/Stokes.hpp"
#include "spectrum/Spectrum.hpp"

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace dropscope {

enum class SourceType { Beam, Ray, PointSource };

std::string_view sourceTypeName(SourceType type);

enum class PolarisationKind { Unpolarised, Linear, Stokes };

// How a beam or a ray source is polarised, as the scene file gives it (docs/scene-format.md, "Sources").
// `reference` is the parallel axis of the frame the state is given in (docs/optics.md, "Polarisation").
struct SourcePolarisation {
    PolarisationKind kind = PolarisationKind::Unpolarised;
    double linearDeg = 0.0;                               // Linear: from the reference towards reference x direction
    StokesVector stokes = unpolarisedStokes();            // Stokes: [I, Q, U, V] as given
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // Linear and Stokes, as given

    // The state in the reference frame with I = 1: (1, cos 2A, sin 2A, 0) for linear light at A degrees.
    StokesVector unitStokes() const;

    friend bool operator==(const SourcePolarisation&, const SourcePolarisation&) = default;
};

// Where photons come from. beam: uniform over a disk of `radius` perpendicular to `direction`;
// ray: a pencil along `direction`; point: isotropic from `origin` (direction unused), unpolarised.
// Beams and rays with a divergence send each photon in a direction uniform over the cone of that half-angle
// around `direction`. Each photon's wavelength is drawn from `spectrum` (docs/spectra.md, "Spectra").
struct Source {
    SourceType type = SourceType::Ray;
    Point origin = Point::Zero();
    Direction direction{0.0, 0.0, 1.0};
    double radius = 0.0;
    SourcePolarisation polarisation = {};
    std::optional<Spectrum> spectrum = std::nullopt;  // absent: one line at the scene's wavelength_nm
    double divergenceDeg = 0.0;                       // in [0, kMaxDivergenceDeg); 0 for a point source
};

// A divergence must leave every direction of the cone on the source's side, so that a polarisation
// reference across the axis is never along a photon's direction.
inline constexpr double kMaxDivergenceDeg = 90.0;

// The spectrum a source's photons draw from: its own, or one line at `sceneWavelengthNm`.
Spectrum sourceSpectrum(const Source& source, double sceneWavelengthNm);

// The shortest and the longest wavelength of all the sources' spectra (docs/cli.md, angular_spectral.csv).
std::pair<double, double> wavelengthRangeNm(const std::vector<Source>& sources, double sceneWavelengthNm);

// Throws std::invalid_argument naming what is wrong (not where) for a divergence that is not finite, negative,
// at least kMaxDivergenceDeg, or non-zero on a point source.
void checkDivergence(const Source& source);

// Each throws std::invalid_argument, with a message naming what is wrong but not where: a Stokes vector
// with I <= 0, a component that is not finite, or Q^2 + U^2 + V^2 > I^2 (tolerance::kStokesDegreeSlack);
// a reference that is not finite, zero, or further from perpendicular to `direction` than
// tolerance::kReferencePerpendicularCosine.
void checkPolarisationStokes(const StokesVector& stokes);
void checkPolarisationReference(const Eigen::Vector3d& reference, const Direction& direction);

// Throws std::invalid_argument, with a message naming what is wrong but not where, when the source's
// polarisation cannot be used: on a point source; a linear angle that is not finite; a reference that is
// not finite, zero, or further from perpendicular to the direction than tolerance::kReferencePerpendicularCosine;
// a Stokes vector with I <= 0, a component that is not finite, or Q^2 + U^2 + V^2 > I^2
// (tolerance::kStokesDegreeSlack).
void checkPolarisation(const Source& source);

}  // namespace dropscope
