#include "transport/RayTree.hpp"

#include "transport/PolarisedCrossing.hpp"

#include <cmath>
#include <stdexcept>

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
    std::optional<Polarisation> light;  // I == weight
};

// Beer-Lambert along a stretch: the branch's weight, and with it its whole Stokes vector, times `factor`.
void attenuate(Branch& branch, double factor) {
    branch.weight *= factor;
    if (branch.light) branch.light->stokes *= factor;
}

}  // namespace

RayTree traceRayTree(const OpticalScene& scene, const Ray& ray, double weight, const RayTreeSettings& settings,
                     const std::optional<Polarisation>& polarisation) {
    const bool polarised = settings.polarisation == PolarisationModel::Stokes;
    if (polarised && settings.fresnel != FresnelModel::Exact) {
        throw std::invalid_argument("Schlick's approximation is unpolarised: trace it without polarisation");
    }
    RayTree tree;
    tree.inputWeight = weight;
    const ShapeId startRegion = scene.regionAt(ray.origin, ray.direction);
    const MediumId startMedium = scene.mediumIdOf(startRegion);
    Branch start{ray.origin, ray.direction, startRegion, weight, 0, 0, std::nullopt};
    if (polarised) {
        start.light = polarisation ? *polarisation : unpolarisedLight(ray.direction);
        start.light->stokes *= weight;
    }
    Event emission{EventType::Emit, ray.origin,  ray.direction, OpticalScene::kAmbient,
                   startMedium,     startMedium, std::nan(""),  weight};
    emission.polarisation = start.light;
    tree.nodes.push_back({emission, -1, 0});
    // As the photon does: cross the empty ambient up to the scene first (docs/transport.md).
    if (startRegion == OpticalScene::kAmbient) {
        const double approach = scene.approachDistance(start.position, ray.direction);
        const double sigma = scene.media()[startMedium].absorptionPerUnit;
        if (approach > 0.0 && sigma > 0.0) {
            attenuate(start, std::exp(-sigma * approach));
            tree.absorbed += weight - start.weight;
        }
        start.position += approach * ray.direction.vector();
    }
    std::vector<Branch> pending{start};

    while (!pending.empty()) {
        Branch branch = pending.back();
        pending.pop_back();
        const MediumId medium = scene.mediumIdOf(branch.region);
        const auto leaf = [&](EventType type, double leafWeight, LostReason reason = LostReason::EventCap) {
            Event event{type,   branch.position, branch.direction, OpticalScene::kAmbient,
                        medium, medium,          std::nan(""),     leafWeight};
            event.lostReason = reason;
            event.polarisation = branch.light;
            if (event.polarisation && leafWeight == 0.0) event.polarisation->stokes.setZero();
            tree.nodes.push_back({event, branch.parent, branch.depth});
        };
        if (branch.weight < settings.minWeight || branch.depth >= settings.maxDepth) {
            leaf(EventType::Truncated, branch.weight);
            continue;
        }

        const RayHit hit = scene.nextSurface(branch.region, branch.position, branch.direction);
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
            const double before = branch.weight;
            attenuate(branch, std::exp(-sigma * hit.distance));
            tree.absorbed += before - branch.weight;
            if (branch.weight == 0.0) {  // exp underflowed: nothing reaches the surface
                leaf(EventType::Absorb, 0.0);
                continue;
            }
        }
        const SurfaceCrossing crossing = crossSurface(scene, branch.region, hit.shape, branch.position,
                                                      branch.direction, settings.fresnel, !branch.light);
        if (crossing.kind == SurfaceCrossing::Kind::Lost) {
            leaf(EventType::Lost, branch.weight, crossing.lostReason);
            continue;
        }
        if (crossing.kind == SurfaceCrossing::Kind::Tangent) {
            Branch onward = branch;
            ++onward.depth;
            pending.push_back(onward);
            continue;
        }

        std::optional<PolarisedCrossing> split;
        if (branch.light) split.emplace(*branch.light, crossing);
        const double reflectance = split ? split->reflectance() : crossing.reflectance;
        // The child along `direction`: with polarisation its light is M S and its weight that light's I;
        // without, the weight is the parent's times `share`.
        const auto addChild = [&](EventType type, const Direction& direction, ShapeId region, double share,
                                  std::optional<Polarisation> light) {
            const double childWeight = light ? light->stokes[0] : branch.weight * share;
            if (childWeight <= 0.0) return;
            const auto node = static_cast<std::int32_t>(tree.nodes.size());
            Event event{type,          branch.position, direction,   hit.shape,
                        crossing.from, crossing.to,     reflectance, childWeight};
            event.polarisation = light;
            tree.nodes.push_back({event, branch.parent, branch.depth + 1});
            pending.push_back({branch.position, direction, region, childWeight, node, branch.depth + 1, light});
        };
        const auto reflected = [&] { return split ? std::optional(split->reflected()) : std::nullopt; };
        if (crossing.totalInternalReflection) {
            addChild(EventType::Tir, crossing.reflected(), branch.region, 1.0, reflected());
        } else {
            addChild(EventType::Refract, crossing.transmitted, crossing.regionBeyond, 1.0 - reflectance,
                     split ? std::optional(split->transmitted()) : std::nullopt);
            addChild(EventType::Reflect, crossing.reflected(), branch.region, reflectance, reflected());
        }
    }
    return tree;
}

}  // namespace dropscope
