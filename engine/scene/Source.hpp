#pragma once

#include "geometry/Vector.hpp"
#include "optics/Stokes.hpp"

#include <string_view>

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
struct Source {
    SourceType type = SourceType::Ray;
    Point origin = Point::Zero();
    Direction direction{0.0, 0.0, 1.0};
    double radius = 0.0;
    SourcePolarisation polarisation = {};
};

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
