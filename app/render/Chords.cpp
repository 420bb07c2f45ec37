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
    const Shape* shape = octree.shape(id);
    if (shape == nullptr || (shape->kind() != ShapeKind::Sphere && shape->kind() != ShapeKind::Ellipsoid)) return false;
    // The shape as it is now, which an edit after the trace may have moved off the path.
    return shape->locatePoint(from.position) != PointLocation::Outside &&
           shape->locatePoint(to.position) != PointLocation::Outside;
}

}  // namespace dropscope::render
