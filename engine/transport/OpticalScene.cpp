#include "transport/OpticalScene.hpp"

#include "geometry/Ellipsoid.hpp"
#include "geometry/Sphere.hpp"
#include "scene/SceneOverlaps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <typeinfo>

namespace dropscope {

namespace {

std::vector<std::unique_ptr<Shape>> cloneShapes(const Scene& scene) {
    std::vector<std::unique_ptr<Shape>> copies;
    copies.reserve(scene.shapes.size());
    for (const auto& shape : scene.shapes) copies.push_back(shape ? shape->clone() : nullptr);
    return copies;
}

}  // namespace

Direction OpticalScene::normalOf(ShapeId shape, const Point& p) const {
    const ShapeFacts& facts = factsOf(shape);
    if (!facts.isSphere) return octree_.shape(shape)->normal(p);
    // Sphere::normal, on the octree's copy of its geometry.
    const SphereGeometry sphere = octree_.packedSphere(shape);
    if (sphere.locate(p) != PointLocation::OnSurface) return Direction::invalid();
    return Direction(p - sphere.center);
}

RayHit OpticalScene::nextSurface(ShapeId region, const Point& p, const Direction& d) const {
    if (sealed(region)) {
        RayHit exit;
        exit.offer(region, octree_.packedSphere(region).distanceToSurface(p, d));
        if (exit) return exit;
    }
    return octree_.firstHit(p, d);
}

namespace {

// From inside `inner` (its band included) a ray meets its own surface within the ball grown by its band; the
// other surface is met only on its own band. Each clearance below is two bands each, so the rounding of the
// centres' distance (a few eps of |centre|, far below kCoordinateRelative x |centre| in every band) never
// decides.
bool sphereClearOf(const SphereGeometry& inner, const SphereGeometry& outer) {
    const double betweenSquared = (outer.center - inner.center).squaredNorm();
    const double bands = 2.0 * (inner.band + outer.band);
    const double apart = inner.radius + outer.radius + bands;
    if (betweenSquared > apart * apart) return true;
    const double room = outer.radius - inner.radius - bands;  // the other holds it well inside
    return room > 0.0 && betweenSquared < room * room;
}

}  // namespace

bool OpticalScene::clearOf(const SphereGeometry& inner, ShapeId otherId) const {
    if (facts_[otherId].isSphere) return sphereClearOf(inner, octree_.packedSphere(otherId));
    const Shape& other = *octree_.shape(otherId);
    const double grow = 2.0 * inner.band + octree_.margin();
    const Eigen::AlignedBox3d reach(inner.center.array() - (inner.radius + grow),
                                    inner.center.array() + (inner.radius + grow));
    const Eigen::AlignedBox3d otherBounds = other.bounds();
    const Eigen::AlignedBox3d otherReach(otherBounds.min().array() - octree_.margin(),
                                         otherBounds.max().array() + octree_.margin());
    if (!reach.intersects(otherReach)) return true;
    // A box (the one shape besides a sphere that may hold a sphere) is convex, and so is the part of it inside its
    // band: holding the corners of `reach` there, it holds all of `reach`, and its surface lies beyond.
    if (other.kind() != ShapeKind::Box) return false;
    for (int corner = 0; corner < 8; ++corner) {
        if (other.locatePoint(reach.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner))) !=
            PointLocation::Inside)
            return false;
    }
    return true;
}

// A sphere is sealed unless a shape stored on one octree path with it (every shape that could come near it is)
// is not clear of it; a shape inside it never is.
//
// Each shape's geometry rides on the octree path with its id (forEachPairOnAPath's record), so a pair of spheres
// is checked from two records on the path, not from two records read by id: at 1e6 droplets, some 2e7 pairs.
void OpticalScene::findSealedSpheres() {
    for (ShapeFacts& facts : facts_) facts.sealed = facts.isSphere;
    struct OnPath {
        ShapeId id;
        bool isSphere;
        SphereGeometry sphere;  // when isSphere
    };
    const auto unsealUnlessClear = [&](const OnPath& inner, const OnPath& other) {
        if (!inner.isSphere) return;
        const bool clear = other.isSphere ? sphereClearOf(inner.sphere, other.sphere) : clearOf(inner.sphere, other.id);
        if (!clear) facts_[inner.id].sealed = false;
    };
    octree_.forEachPairOnAPath(
        [&](ShapeId id) {
            const bool isSphere = facts_[id].isSphere;
            return OnPath{id, isSphere, isSphere ? octree_.packedSphere(id) : SphereGeometry{Point::Zero(), 0.0, 0.0}};
        },
        [&](const OnPath& a, const OnPath& b) {
            unsealUnlessClear(a, b);
            unsealUnlessClear(b, a);
        });
}

void OpticalScene::findWhetherPackedSpheresAreAlike() {
    std::optional<ShapeFacts> common;
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        if (!octree_.packsSphere(id)) continue;
        const ShapeFacts& facts = facts_[id];
        if (!common) {
            common = facts;
        } else if (facts != *common) {
            return;
        }
    }
    packedSpheresAlike_ = common;
}

OpticalScene::OpticalScene(const Scene& scene, bool haloes)
    : media_(scene.media),
      wavelengthNm_(scene.wavelengthNm),
      unitInMetres_(scene.unitInMetres),
      ambient_(scene.ambient),
      octree_(cloneShapes(scene), scene.octree),
      facts_(octree_.slotCount()) {
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* inner = octree_.shape(id);
        if (!inner) continue;
        ShapeFacts& facts = facts_[id];
        facts.medium = inner->mediumId();
        // Exactly a Sphere (not a type derived from it, which could answer normal() otherwise); one the octree
        // does not pack (none in a real scene) is read through Shape, and never sealed.
        facts.isSphere = typeid(*inner) == typeid(Sphere) && octree_.packsSphere(id);
    }
    findContainers();
    findSealedSpheres();
    findWhetherPackedSpheresAreAlike();
    // The numbers the scene already holds: the light of the scene wavelength is traced exactly as before.
    for (const Medium& medium : media_) sceneOptics_.push_back({medium.n, medium.absorptionPerUnit});
    for (std::size_t i = 0; i < scene.detectors.size(); ++i) {
        const Detector& detector = scene.detectors[i];
        if (detector.type == DetectorType::Plane && detector.absorbing) {
            absorbingPlanes_.push_back({i, detector, planeFrame(detector)});
        }
    }
    if (!haloes) return;
    std::vector<std::unique_ptr<Shape>> rings;
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* shape = octree_.shape(id);
        if (!shape) continue;
        if (shape->kind() == ShapeKind::Sphere) {
            const auto& sphere = static_cast<const Sphere&>(*shape);
            rings.push_back(std::make_unique<Sphere>(sphere.center(), std::sqrt(2.0) * sphere.radius()));
        } else if (shape->kind() == ShapeKind::Ellipsoid) {
            // Scaled by s about the centre, x.M x = 1 becomes x.(M / s^2) x = 1.
            const auto& ellipsoid = static_cast<const Ellipsoid&>(*shape);
            rings.push_back(
                std::make_unique<Ellipsoid>(Ellipsoid::fromMatrix(ellipsoid.center(), 0.5 * ellipsoid.matrix())));
        } else {
            continue;
        }
        haloOwners_.push_back(id);
    }
    haloes_.emplace(std::move(rings), scene.octree);
}

std::optional<OpticalScene::HaloPass> OpticalScene::firstHaloPass(const Point& p, const Direction& d, double length,
                                                                  ShapeId region) const {
    if (!haloes_) throw std::logic_error("firstHaloPass: the scene was built without haloes");
    // From halo surface to halo surface along the flight: Octree::firstHit never returns 0, so from a point on a
    // halo's surface it finds that halo's far side when entering it and the next surface when leaving.
    Point at = p;
    double travelled = 0.0;
    // The nearest middle so far: haloes overlap, and one entered later may have its middle nearer.
    std::optional<HaloPass> nearest;
    for (std::size_t step = 0; step < 2 * haloOwners_.size() + 2; ++step) {
        const double limit = nearest ? std::min(length, nearest->distance) : length;
        const RayHit hit = haloes_->firstHit(at, d);
        if (!hit || travelled + hit.distance >= limit) break;
        travelled += hit.distance;
        at = p + travelled * d.vector();
        const Shape& halo = *haloes_->shape(hit.shape);
        const ShapeId droplet = haloOwners_[hit.shape];
        const Direction normal = halo.normal(at);
        if (!normal || d.dot(normal) >= 0.0 || parentOf(droplet) != region) continue;
        // Entering the halo: a pass when the flight then misses the droplet itself.
        const double chord = halo.distanceToSurface(at, d);
        if (!(chord > 0.0) || !std::isnan(octree_.shape(droplet)->distanceToSurface(at, d))) continue;
        const double middle = travelled + 0.5 * chord;
        if (middle < limit) nearest = HaloPass{droplet, middle};
    }
    return nearest;
}

std::optional<OpticalScene::PlaneHit> OpticalScene::firstAbsorbingPlane(const Point& p, const Direction& d,
                                                                        double length) const {
    std::optional<PlaneHit> first;
    for (const AbsorbingPlane& absorber : absorbingPlanes_) {
        const auto crossing = crossPlane(absorber.plane, absorber.frame, p, d, first ? first->distance : length);
        if (crossing && (!first || crossing->distance < first->distance))
            first = PlaneHit{&absorber, crossing->distance};
    }
    return first;
}

void OpticalScene::opticsAt(double wavelengthNm, std::vector<MediumOptics>& optics) const {
    optics.resize(media_.size());
    for (std::size_t id = 0; id < media_.size(); ++id)
        optics[id] = mediumOpticsAt(media_[id], wavelengthNm, unitInMetres_);
}

// A container encloses the inner shape's centre, so it is stored on the cells along that point's path (shapes
// are convex and symmetric: the centre of the bounds is inside). Every shape whose centre lies in one leaf has
// the same path, so its shapes and their volumes are gathered once a leaf, not once a shape: at 1e6 droplets
// that is the difference between reading each candidate's Shape (a cache miss) some 6e7 times and some 2e6.
// The candidates are tried in the path's order, so ties of volume go to the same shape either way.
void OpticalScene::findContainers() {
    std::vector<std::pair<std::uint32_t, ShapeId>> byLeaf;  // (leaf holding the centre, shape)
    byLeaf.reserve(octree_.shapeCount());
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* shape = octree_.shape(id);
        if (!shape) continue;
        if (const auto leaf = octree_.leafHolding(shape->bounds().center())) byLeaf.emplace_back(*leaf, id);
    }
    std::sort(byLeaf.begin(), byLeaf.end());
    struct Candidate {
        ShapeId id;
        double volume;
        const Shape* shape;
    };
    std::vector<Candidate> candidates;
    for (std::size_t first = 0; first < byLeaf.size();) {
        std::size_t end = first;
        while (end < byLeaf.size() && byLeaf[end].first == byLeaf[first].first) ++end;
        candidates.clear();
        const Point centre = octree_.shape(byLeaf[first].second)->bounds().center();  // any of the group's
        octree_.forEachShapeAlongPath(centre, [&](ShapeId other) {
            const Shape* shape = octree_.shape(other);
            candidates.push_back({other, shape->volume(), shape});
        });
        for (std::size_t k = first; k < end; ++k) {
            const ShapeId innerId = byLeaf[k].second;
            const Shape& inner = *octree_.shape(innerId);
            const double innerVolume = inner.volume();
            ShapeId best = kAmbient;
            double bestVolume = 0.0;
            for (const Candidate& outer : candidates) {
                if (outer.id == innerId || outer.volume <= innerVolume || !nestsInside(inner, *outer.shape)) continue;
                if (best == kAmbient || outer.volume < bestVolume) {
                    best = outer.id;
                    bestVolume = outer.volume;
                }
            }
            facts_[innerId].parent = best;
        }
        first = end;
    }
}

ShapeId OpticalScene::regionAt(const Point& p) const { return octree_.locate(p).value_or(kAmbient); }

ShapeId OpticalScene::regionAt(const Point& p, const Direction& d) const {
    // One walk down the cells holding p: the smallest shape that encloses p, or whose surface band p is
    // on while d points into it (ties to the lower id, as Octree::locate).
    ShapeId region = kAmbient;
    double regionVolume = std::numeric_limits<double>::infinity();
    octree_.forEachShapeAlongPath(p, [&](ShapeId id) {
        const Shape& shape = *octree_.shape(id);
        const double volume = shape.volume();
        if (volume > regionVolume || (volume == regionVolume && id > region)) return;
        const PointLocation location = shape.locatePoint(p);
        if (location == PointLocation::Outside) return;
        if (location == PointLocation::OnSurface) {
            const Direction normal = shape.normal(p);
            if (!normal || d.dot(normal) >= 0.0) return;
        }
        region = id;
        regionVolume = volume;
    });
    return region;
}

double OpticalScene::approachDistance(const Point& p, const Direction& d, bool haloes) const {
    const std::optional<std::pair<double, double>> span = octree_.rootSpan(p, d);
    if (!haloes || !haloes_) return span ? span->first : 0.0;
    // The haloes reach beyond the shapes: the first flight must start before the nearer of the two roots.
    const std::optional<std::pair<double, double>> haloSpan = haloes_->rootSpan(p, d);
    if (span && haloSpan) return std::min(span->first, haloSpan->first);
    if (span) return span->first;
    return haloSpan ? haloSpan->first : 0.0;
}

}  // namespace dropscope
