#include "render/Chords.hpp"

namespace dropscope::render {

namespace {

bool atInterface(const Event& event) {
    return event.type == EventType::Reflect || event.type == EventType::Refract || event.type == EventType::Tir;
}

}  // namespace

bool isChord(const Event& from, const Event& to, const Octree& octree, const std::vector<ShapeId>* slotOfShape) {
    if (from.shape == RayHit::kNone || from.shape != to.shape || !atInterface(from) || !atInterface(to)) return false;
    ShapeId id = from.shape;
    if (slotOfShape) id = id < slotOfShape->size() ? (*slotOfShape)[id] : RayHit::kNone;
    // The shape as it is now, which an edit after the trace may have moved off the path. The octree's own copy
    // of a sphere it packs is the same geometry in one array, where the shape itself is two loads away at random
    // (its pointer, then the object): a ray tree through 1e6 droplets asks this 3e5 times.
    if (octree.packsSphere(id)) {
        const SphereGeometry sphere = octree.packedSphere(id);
        return sphere.locate(from.position) != PointLocation::Outside &&
               sphere.locate(to.position) != PointLocation::Outside;
    }
    const Shape* shape = octree.shape(id);
    if (shape == nullptr || (shape->kind() != ShapeKind::Sphere && shape->kind() != ShapeKind::Ellipsoid)) return false;
    return shape->locatePoint(from.position) != PointLocation::Outside &&
           shape->locatePoint(to.position) != PointLocation::Outside;
}

}  // namespace dropscope::render
