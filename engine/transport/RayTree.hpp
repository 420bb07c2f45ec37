#pragma once

#include "transport/Emission.hpp"
#include "transport/Event.hpp"
#include "transport/OpticalScene.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace dropscope {

struct RayTreeSettings {
    double minWeight = 1e-6;  // a branch lighter than this ends in a Truncated leaf
    int maxDepth = 64;        // interface events along one branch before it is truncated
    FresnelModel fresnel = FresnelModel::Exact;
    PolarisationModel polarisation = PolarisationModel::Stokes;  // Stokes needs FresnelModel::Exact
};

struct RayTreeNode {
    Event event;          // event.weight: the branch's weight leaving this event
    std::int32_t parent;  // -1 for the emission (node 0)
    int depth;            // interface events between the emission and this node
};

// Every branch of one ray, for the debugger: at each interface both the reflected (weight R) and the
// refracted (weight 1 - R) branch are followed, attenuated by Beer-Lambert exp(-sigma s) along each
// segment. Leaves are escapes, truncations, losses and total absorptions (an absorbing medium with no
// surface ahead); their weights add up to the input weight minus `absorbed`. With
// PolarisationModel::Stokes every branch carries its Stokes vector (event.polarisation, I = the
// branch's weight): the reflected branch M_R S, the refracted M_T S, both attenuated alike.
struct RayTree {
    std::vector<RayTreeNode> nodes;  // parents before children
    double inputWeight = 1.0;
    double absorbed = 0.0;

    std::vector<bool> leaves() const;  // leaves()[i]: node i has no child
    double leafWeight() const;
};

// `polarisation` is the ray's light at unit power (unpolarisedLight when absent); it is scaled by `weight`.
// Throws std::invalid_argument for Stokes with Schlick's approximation.
RayTree traceRayTree(const OpticalScene& scene, const Ray& ray, double weight, const RayTreeSettings& settings,
                     const std::optional<Polarisation>& polarisation = std::nullopt);

}  // namespace dropscope
