#include "transport/OpticalScene.hpp"

#include "scene/SceneOverlaps.hpp"

namespace dropscope {

namespace {

std::vector<std::unique_ptr<Shape>> cloneShapes(const Scene& scene) {
    std::vector<std::unique_ptr<Shape>> copies;
    copies.reserve(scene.shapes.size());
    for (const auto& shape : scene.shapes) copies.push_back(shape ? shape->clone() : nullptr);
    return copies;
}

}  // namespace

OpticalScene::OpticalScene(const Scene& scene)
    : media_(scene.media), ambient_(scene.ambient), octree_(cloneShapes(scene), scene.octree),
      parents_(octree_.slotCount(), kAmbient) {
    for (ShapeId id = 0; id < octree_.slotCount(); ++id) {
        const Shape* inner = octree_.shape(id);
        if (!inner) continue;
        for (ShapeId other : octree_.overlapping(*inner)) {
            const Shape& outer = *octree_.shape(other);
            if (!nestsInside(*inner, outer)) continue;
            if (parents_[id] == kAmbient || outer.volume() < octree_.shape(parents_[id])->volume()) parents_[id] = other;
        }
    }
}

ShapeId OpticalScene::regionAt(const Point& p) const {
    return octree_.locate(p).value_or(kAmbient);
}

}  // namespace dropscope
