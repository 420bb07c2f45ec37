#include "tree/RayHit.hpp"

namespace dropscope {

RayHit bruteForceFirstHit(const std::vector<std::unique_ptr<Shape>>& shapes, const Point& p, const Direction& d) {
    RayHit hit;
    for (std::size_t id = 0; id < shapes.size(); ++id) {
        if (shapes[id]) hit.offer(static_cast<ShapeId>(id), shapes[id]->distanceToSurface(p, d));
    }
    return hit;
}

}  // namespace dropscope
