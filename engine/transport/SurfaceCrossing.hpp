#pragma once

#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"

namespace dropscope {

// Which reflectance a surface uses: the exact Fresnel equations, or Schlick's approximation to compare.
enum class FresnelModel { Exact, Schlick };

// Everything that can happen where a ray meets a surface, shared by the Monte Carlo photon and the
// ray tree: the media on both sides, the Fresnel reflectance and both outgoing directions.
struct SurfaceCrossing {
    enum class Kind { Interface, Tangent, Lost };
    Kind kind = Kind::Lost;
    LostReason lostReason = LostReason::MediumMismatch;  // when kind == Lost
    ShapeId regionBeyond = OpticalScene::kAmbient;       // the region a transmitted ray enters
    MediumId from = 0;
    MediumId to = 0;
    double reflectance = 1.0;  // unpolarised R, 1 on total internal reflection
    bool totalInternalReflection = false;
    Direction reflected;
    Direction transmitted;  // invalid on total internal reflection
};

// The ray travelling along `direction` in `region` has reached `point` on `shape`'s surface (a hit
// returned by the octree, so within the shape's surface band). The outward normal's side tells
// whether it enters or leaves `shape`; that must agree with `region`, or the crossing is lost.
SurfaceCrossing crossSurface(const OpticalScene& scene, ShapeId region, ShapeId shape, const Point& point,
                             const Direction& direction, FresnelModel fresnel);

}  // namespace dropscope
