#include "transport/RayTree.hpp"

#include <cmath>

namespace dropscope {

std::vector<bool> RayTree::leaves() const {
    std::vector<bool> leaf(nodes.size(), true);
    for (const RayTreeNode& node : nodes) {
        if (node.parent >= 0) leaf[static_cast<std::size_t>(node.parent)] = false;
    }
    return leaf;
}

double RayTree::leafWeight() const {
    const std::vector<bool> leaf = leaves();
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (leaf[i]) sum += nodes[i].event.weight;
    }
    return sum;
}

namespace {

struct Branch {
    Point position;
    Direction direction;
    ShapeId region;
    double weight;
    std::int32_t parent;
    int depth;
};

}  // namespace

RayTree traceRayTree(const OpticalScene& scene, const Ray& ray, double weight, const RayTreeSettings& settings) {
    RayTree tree;
    tree.inputWeight = weight;
    const ShapeId startRegion = scene.regionAt(ray.origin, ray.direction);
    const MediumId startMedium = scene.mediumIdOf(startRegion);
    tree.nodes.push_back({Event{EventType::Emit, ray.origin, ray.direction, OpticalScene::kAmbient, startMedium,
                                startMedium, std::nan(""), weight},
                          -1, 0});
    // As the photon does: cross the empty ambient up to the scene first (docs/transport.md).
    Point start = ray.origin;
    double startWeight = weight;
    if (startRegion == OpticalScene::kAmbient) {
        const double approach = scene.approachDistance(start, ray.direction);
        const double sigma = scene.media()[startMedium].absorptionPerUnit;
        if (approach > 0.0 && sigma > 0.0) {
            startWeight = weight * std::exp(-sigma * approach);
            tree.absorbed += weight - startWeight;
        }
        start += approach * ray.direction.vector();
    }
    std::vector<Branch> pending{{start, ray.direction, startRegion, startWeight, 0, 0}};

    while (!pending.empty()) {
        Branch branch = pending.back();
        pending.pop_back();
        const MediumId medium = scene.mediumIdOf(branch.region);
        const auto leaf = [&](EventType type, double leafWeight, LostReason reason = LostReason::EventCap) {
            Event event{type,   branch.position, branch.direction, OpticalScene::kAmbient,
                        medium, medium,          std::nan(""),     leafWeight};
            event.lostReason = reason;
            tree.nodes.push_back({event, branch.parent, branch.depth});
        };
        if (branch.weight < settings.minWeight || branch.depth >= settings.maxDepth) {
            leaf(EventType::Truncated, branch.weight);
            continue;
        }

        const RayHit hit = scene.octree().firstHit(branch.position, branch.direction);
        const double sigma = scene.media()[medium].absorptionPerUnit;
        if (!hit) {
            if (sigma > 0.0) {
                tree.absorbed += branch.weight;
                leaf(EventType::Absorb, 0.0);
            } else if (branch.region != OpticalScene::kAmbient) {
                leaf(EventType::Lost, branch.weight, LostReason::NoExit);
            } else {
                leaf(EventType::Escape, branch.weight);
            }
            continue;
        }

        branch.position += hit.distance * branch.direction.vector();
        if (sigma > 0.0) {
            const double transmitted = branch.weight * std::exp(-sigma * hit.distance);
            tree.absorbed += branch.weight - transmitted;
            branch.weight = transmitted;
            if (transmitted == 0.0) {  // exp underflowed: nothing reaches the surface
                leaf(EventType::Absorb, 0.0);
                continue;
            }
        }
        const SurfaceCrossing crossing =
            crossSurface(scene, branch.region, hit.shape, branch.position, branch.direction, settings.fresnel);
        if (crossing.kind == SurfaceCrossing::Kind::Lost) {
            leaf(EventType::Lost, branch.weight, crossing.lostReason);
            continue;
        }
        if (crossing.kind == SurfaceCrossing::Kind::Tangent) {
            pending.push_back(
                {branch.position, branch.direction, branch.region, branch.weight, branch.parent, branch.depth + 1});
            continue;
        }

        const auto split = [&](EventType type, const Direction& direction, ShapeId region, double share) {
            const double branchWeight = branch.weight * share;
            if (branchWeight <= 0.0) return;
            const auto node = static_cast<std::int32_t>(tree.nodes.size());
            tree.nodes.push_back({Event{type, branch.position, direction, hit.shape, crossing.from, crossing.to,
                                        crossing.reflectance, branchWeight},
                                  branch.parent, branch.depth + 1});
            pending.push_back({branch.position, direction, region, branchWeight, node, branch.depth + 1});
        };
        if (crossing.totalInternalReflection) {
            split(EventType::Tir, crossing.reflected, branch.region, 1.0);
        } else {
            split(EventType::Refract, crossing.transmitted, crossing.regionBeyond, 1.0 - crossing.reflectance);
            split(EventType::Reflect, crossing.reflected, branch.region, crossing.reflectance);
        }
    }
    return tree;
}

}  // namespace dropscope
