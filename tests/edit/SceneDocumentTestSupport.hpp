#pragma once

// Shared by the SceneDocument tests: a small scene, shape specs, and what a refused edit must leave alone.
#include "edit/SceneDocument.hpp"

#include "scene/SceneLoader.hpp"
#include "scene/SceneWriter.hpp"

#include <functional>
#include <string>

namespace dropscope::test {

// Two named water droplets in air, and a glass cell above them.
inline Scene smallScene() {
    return parseScene(R"({"dropscope": 1, "ambient": "air",
        "media": {"air": {"n": 1.0}, "water": {"n": 1.333, "kappa": 1e-9}, "glass": {"n": 1.5}},
        "shapes": [
          {"type": "sphere", "name": "d1", "center": [0, 0, 0], "radius": 1, "medium": "water"},
          {"type": "sphere", "name": "d2", "center": [3, 0, 0], "radius": 1, "medium": "water"},
          {"type": "box", "name": "cell", "min": [-5, -5, 5], "max": [5, 5, 10], "medium": "glass"}],
        "sources": [{"type": "ray", "origin": [0, 0, -10], "direction": [0, 0, 1]}]})",
                      "small.json");
}

inline ShapeSpec sphereAt(const Point& center, double radius, MediumId medium = 1) {
    ShapeSpec spec;
    spec.center = center;
    spec.radius = radius;
    spec.medium = medium;
    return spec;
}

// A plane detector 20 above the droplets, facing them.
inline Detector screen(const std::string& name = "screen") {
    Detector plane;
    plane.name = name;
    plane.center = Point(0, 0, 20);
    plane.normal = Direction(0, 0, -1);
    plane.size = {8.0, 6.0};
    plane.pixels = {32, 24};
    return plane;
}

// The shape firstHit finds from `origin` along `direction`, or RayHit::kNone.
inline ShapeId hitFrom(const SceneDocument& document, const Point& origin, const Eigen::Vector3d& direction) {
    return document.octree().firstHit(origin, Direction(direction)).shape;
}

inline std::string refusalOf(const std::function<void()>& edit) {
    try {
        edit();
    } catch (const EditRefused& refusal) {
        return refusal.what();
    }
    return "accepted";
}

// Everything a refused edit must leave alone.
struct Snapshot {
    std::uint64_t revision;
    std::size_t shapes;
    std::size_t slots;
    std::size_t undo;
    std::size_t redo;
    std::string text;
    explicit Snapshot(const SceneDocument& d)
        : revision(d.revision()),
          shapes(d.shapeCount()),
          slots(d.slotCount()),
          undo(d.undoDepth()),
          redo(d.redoDepth()),
          text(sceneToJson(d.toScene())) {}
    bool operator==(const Snapshot&) const = default;
};

}  // namespace dropscope::test
