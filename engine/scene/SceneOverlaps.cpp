#include "scene/SceneOverlaps.hpp"

#include "geometry/Box.hpp"
#include "geometry/Sphere.hpp"
#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"

namespace dropscope {

namespace {

// `sphere "d1"`, or just `box` for an unnamed shape.
std::string describe(const Scene& scene, std::size_t id) {
    std::string text(scene.shapes[id]->typeName());
    if (!scene.shapeNames[id].empty()) text.append(" ").append(jsonpath::quoted(scene.shapeNames[id]));
    return text;
}

}  // namespace

bool nestsInside(const Shape& inner, const Shape& outer) {
    if (outer.kind() == ShapeKind::Box) return static_cast<const Box&>(outer).encloses(inner);
    if (outer.kind() == ShapeKind::Sphere && inner.kind() == ShapeKind::Sphere) {
        const auto& big = static_cast<const Sphere&>(outer);
        const auto& small = static_cast<const Sphere&>(inner);
        // Touching from inside is allowed, within the outer sphere's surface band.
        return (big.center() - small.center()).norm() + small.radius() <= big.radius() + big.surfaceBand();
    }
    return false;
}

void checkShapesDisjoint(const Scene& scene) {
    for (std::size_t later = 1; later < scene.shapes.size(); ++later) {
        const Shape& b = *scene.shapes[later];
        for (std::size_t earlier = 0; earlier < later; ++earlier) {
            const Shape& a = *scene.shapes[earlier];
            if (!a.overlaps(b) || nestsInside(a, b) || nestsInside(b, a)) continue;
            throw SceneError(scene.origin, jsonpath::element("shapes", later),
                             describe(scene, later) + " overlaps " + jsonpath::element("shapes", earlier) + " (" +
                                 describe(scene, earlier) +
                                 "); shapes may touch or nest (anything in a box, a sphere in a sphere), "
                                 "not partly overlap");
        }
    }
}

}  // namespace dropscope
