#pragma once

#include "scene/Detector.hpp"
#include "scene/Medium.hpp"
#include "scene/Scene.hpp"
#include "tree/Octree.hpp"

#include <optional>
#include <vector>

namespace dropscope {

// What photon transport needs of a scene: the octree over its shapes, the media, and which region of
// space every point belongs to. A region is the innermost shape around a point, or RayHit::kNone for
// the ambient medium outside every shape. Shapes nest but never partly overlap (the loader refuses
// that), so each shape has one parent region: the smallest shape it nests in, or the ambient.
class OpticalScene {
public:
    static constexpr ShapeId kAmbient = RayHit::kNone;

    // Clones the scene's shapes and finds each one's parent along the octree path of its centre. With
    // `haloes`, also indexes every sphere's and ellipsoid's halo for diffraction (firstHaloPass).
    explicit OpticalScene(const Scene& scene, bool haloes = false);

    const Octree& octree() const { return octree_; }
    const std::vector<Medium>& media() const { return media_; }
    double wavelengthNm() const { return wavelengthNm_; }
    double unitInMetres() const { return unitInMetres_; }
    // Every medium's n and absorption at the scene wavelength, by medium id.
    const std::vector<MediumOptics>& sceneOptics() const { return sceneOptics_; }
    // The same at `wavelengthNm` into `optics` (at the scene wavelength, the same values as sceneOptics()).
    void opticsAt(double wavelengthNm, std::vector<MediumOptics>& optics) const;

    // The region a point lies in (a point on a surface band belongs to the region around that shape).
    ShapeId regionAt(const Point& p) const;
    // The region a photon at p travelling along d is in: as regionAt(p), except that on a shape's
    // surface band heading into the shape it is already inside that shape.
    ShapeId regionAt(const Point& p, const Direction& d) const;
    // How far a ray from p must travel to reach the octree's root cell, outside which there is
    // nothing but the ambient medium: 0 when p is inside it or the ray misses it. `haloes`: also stop short of
    // every halo (for diffraction; the scene must have them).
    double approachDistance(const Point& p, const Direction& d, bool haloes = false) const;
    // The region on the outside of `shape`'s surface.
    ShapeId parentOf(ShapeId shape) const { return factsOf(shape).parent; }
    MediumId mediumIdOf(ShapeId region) const { return region == kAmbient ? ambient_ : factsOf(region).medium; }
    // The first surface a photon in `region` at p meets along d: exactly Octree::firstHit (the same shape and
    // distance), but inside a sealed sphere it is that sphere's far side, found without a search. p must lie in
    // `region` or on its surface band, as a photon's position always does.
    RayHit nextSurface(ShapeId region, const Point& p, const Direction& d) const;
    // Whether `shape` is a sphere no other surface comes near enough to be met first from inside it: it holds no
    // shape, and every other shape is clear of it or holds it well inside (docs/transport.md, "Sealed droplets").
    // False for kAmbient and empty slots.
    bool sealed(ShapeId shape) const { return shape < facts_.size() && factsOf(shape).sealed; }
    // Whether every sphere the octree packs has the same medium, parent and sealing (a cloud of like droplets),
    // so that a crossing reads them without a load at the sphere's id.
    bool packedSpheresAlike() const { return packedSpheresAlike_.has_value(); }
    // Shape::normal of `shape` at p (the same bits), without reading a sphere's Shape object.
    Direction normalOf(ShapeId shape, const Point& p) const;
    const Medium& mediumOf(ShapeId region) const { return media_[mediumIdOf(region)]; }

    // The scene's absorbing plane detectors, which end the photons they count (docs/detectors.md).
    struct AbsorbingPlane {
        std::size_t detector;  // index in the scene's detectors
        Detector plane;
        PlaneFrame frame;
    };
    // The nearest absorbing plane a flight from p along d crosses within (0, length], if any.
    struct PlaneHit {
        const AbsorbingPlane* plane;
        double distance;
    };
    std::optional<PlaneHit> firstAbsorbingPlane(const Point& p, const Direction& d, double length) const;

    // Diffraction (docs/transport.md, "Diffraction"): a droplet's halo is its body scaled by sqrt 2 about its
    // centre, so the ring between outline and halo outline is as large as the outline, whatever the direction.
    // A flight through that ring passes the droplet and is diffracted by it, at the middle of its chord through the
    // halo. The nearest such pass (by its middle) within (0, length) of a flight from p along d in `region` (only
    // droplets whose outside is `region` count, and only haloes the flight enters, not one it starts in), if any. Needs
    // haloes.
    struct HaloPass {
        ShapeId droplet;
        double distance;
    };
    bool hasHaloes() const { return haloes_.has_value(); }
    std::optional<HaloPass> firstHaloPass(const Point& p, const Direction& d, double length, ShapeId region) const;

private:
    // Each shape's parent: the smallest shape it nests inside (nestsInside), or kAmbient.
    void findContainers();
    // Whether no ray from inside sphere `inner` can meet shape `other`'s surface before its own.
    bool clearOf(const SphereGeometry& inner, ShapeId other) const;
    void findSealedSpheres();
    void findWhetherPackedSpheresAreAlike();

    std::vector<Medium> media_;
    double wavelengthNm_;
    double unitInMetres_;
    std::vector<MediumOptics> sceneOptics_;
    MediumId ambient_;
    Octree octree_;
    // What a photon's surface crossing reads of a shape, by shape id in one record: without it each crossing
    // made three dependent loads (the octree's Shape pointer, the object, its vtable) into memory laid out
    // unrelated to space (docs/performance.md, "Photon transport"). A sphere's geometry is the octree's
    // (Octree::packedSphere), which the search has just read for the hit, so the record is 12 bytes.
    struct ShapeFacts {
        MediumId medium = 0;
        ShapeId parent = kAmbient;
        bool isSphere = false;  // exactly a Sphere, and the octree packs it
        bool sealed = false;
        bool operator==(const ShapeFacts&) const = default;
    };
    std::vector<ShapeFacts> facts_;
    // When every sphere the octree packs has the same record (a cloud of like droplets, the common scene), that
    // record: a packed sphere's is then read here, and the one load per crossing left at a shape's id (1.2 MB
    // at 1e5 droplets, read at random) is not made. Whether a shape is packed is in the octree's record of it,
    // which the search has just read.
    std::optional<ShapeFacts> packedSpheresAlike_;
    const ShapeFacts& factsOf(ShapeId id) const {
        return packedSpheresAlike_ && octree_.packsSphere(id) ? *packedSpheresAlike_ : facts_[id];
    }
    std::vector<AbsorbingPlane> absorbingPlanes_;
    std::optional<Octree> haloes_;
    std::vector<ShapeId> haloOwners_;  // the droplet of each halo, by halo id
};

}  // namespace dropscope
