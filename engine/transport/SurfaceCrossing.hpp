#pragma once

#include "optics/Interface.hpp"
#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"

#include <span>
#include <string_view>

namespace dropscope {

// Which reflectance a surface uses: the exact Fresnel equations, or Schlick's approximation to compare.
enum class FresnelModel { Exact, Schlick };

// How light is reflected and transmitted: `Stokes` carries each photon's Stokes vector through every
// interface with the Mueller matrices of the Fresnel amplitudes (docs/optics.md, "Polarisation");
// `None` reflects every photon with the unpolarised reflectance (Rs + Rp)/2, the model before polarisation.
enum class PolarisationModel { Stokes, None };

std::string_view polarisationModelName(PolarisationModel model);  // "stokes", "none"

// Everything that can happen where a ray meets a surface, shared by the Monte Carlo photon and the
// ray tree: the media on both sides, the Fresnel reflectance and both outgoing directions.
struct SurfaceCrossing {
    enum class Kind { Interface, Tangent, Lost };
    Kind kind = Kind::Lost;
    LostReason lostReason = LostReason::MediumMismatch;  // when kind == Lost
    ShapeId regionBeyond = OpticalScene::kAmbient;       // the region a transmitted ray enters
    MediumId from = 0;
    MediumId to = 0;
    double reflectance = 1.0;  // unpolarised R, 1 on total internal reflection; NaN when not asked for
    bool totalInternalReflection = false;
    Direction normal;           // the shape's outward normal at the point
    double cosIncidence = 1.0;  // |direction . normal|
    double n1 = 1.0;            // index on the incident side
    double n2 = 1.0;            // index on the far side
    Direction incident;         // the ray's direction as it arrived
    Direction transmitted;      // invalid on total internal reflection
    // Worked out when asked: most crossings of a photon transmit, and the direction costs a normalisation.
    Direction reflected() const { return reflect(incident, normal); }
};

// The ray travelling along `direction` in `region` has reached `point` on `shape`'s surface (a hit
// returned by the octree, so within the shape's surface band). The outward normal's side tells
// whether it enters or leaves `shape`; that must agree with `region`, or the crossing is lost. The
// unpolarised reflectance is computed only when `unpolarisedReflectance` (polarised light has its own,
// PolarisedCrossing). The indices are those of `optics` (by medium id: the ray's wavelength), or the scene
// wavelength's when it is empty.
SurfaceCrossing crossSurface(const OpticalScene& scene, ShapeId region, ShapeId shape, const Point& point,
                             const Direction& direction, FresnelModel fresnel, bool unpolarisedReflectance = true,
                             std::span<const MediumOptics> optics = {});

}  // namespace dropscope
