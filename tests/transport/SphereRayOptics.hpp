#pragma once

// Geometric optics of a homogeneous sphere under a wide, unpolarised, parallel beam, integrated over the
// impact parameter ray order by ray order with the s and p polarisations tracked apart: the reference for
// the tracer's polarisation. The derivation, the quadrature and its accuracy are in docs/validation.md,
// "Ray optics of a sphere with s and p tracked". It is a second derivation on purpose: plain C++, nothing
// from engine/ (the Fresnel formulae are written out here again).
//
// Units: angles in radians inside, degrees in the interface (as named); lengths in sphere radii.
// Every power is a fraction of the power incident on the sphere (a beam exactly as wide as the sphere).

#include "transport/SphereRay.hpp"
#include "transport/SphereRayOpticsQuadrature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dropscope::testing {

// What one ray order (or a set of them) sends out.
struct RayOrderPower {
    PowerFraction total;              // in every direction, integrated over the impact parameter alone
    std::vector<PowerFraction> bins;  // per angular bin; they add up to `total`
};

// The answer of sphereRayOptics. Every PowerFraction is a fraction of the power incident on the sphere (see
// PowerFraction: s and p of the incident s and p power, I = (s + p)/2 of unpolarised light). Bin i holds the
// power escaping at scattering angles between binEdgesDegrees[i] and [i + 1] (0 = forward).
struct SphereRayOptics {
    std::vector<double> binEdgesDegrees;  // as given: increasing from 0 to 180
    std::vector<RayOrderPower> orders;    // p = 0 (outer reflection), 1 (straight through), 2 (primary bow), ...
    RayOrderPower higherOrders;           // every order above the last of `orders`, summed
    std::vector<PowerFraction> bins;      // every order
    PowerFraction absorbed;
    PowerFraction escaped;                     // 1 - absorbed
    PowerFraction backscattered;               // escaping at scattering angles above 90 degrees
    double asymmetry = 0.0;                    // g = <cos theta> over the escaping power alone, s and p tracked
    double asymmetryUnpolarisedFresnel = 0.0;  // the same for the unpolarised-Fresnel model
    // Orders too high to follow ray by ray (2e-12 of the power for water, 1.5e-11 for m = 3), spread evenly in angle.
    PowerFraction unresolvedTail;
};

// The sphere of relative index m > 1 and absorption sigmaA = sigma * radius (a chord of theta_t transmits
// exp(-2 sigmaA cos theta_t)) under a wide unpolarised beam: orders 0..maxOrder one by one, the rest summed,
// into the angular bins between binEdgesDegrees (increasing, from 0 to 180, any widths). `refinement` splits
// every quadrature panel and tail step that many times (2 against 1 measures the quadrature error).
inline SphereRayOptics sphereRayOptics(double m, double sigmaA, const std::vector<double>& binEdgesDegrees,
                                       int maxOrder, int refinement = 1) {
    using namespace sphere_optics_detail;
    if (!(m > 1.0) || !(sigmaA >= 0.0) || maxOrder < 0 || refinement < 1)
        throw std::invalid_argument("sphereRayOptics: needs m > 1, sigmaA >= 0, maxOrder >= 0, refinement >= 1");
    if (binEdgesDegrees.size() < 2 || binEdgesDegrees.front() != 0.0 || binEdgesDegrees.back() != 180.0 ||
        !std::is_sorted(binEdgesDegrees.begin(), binEdgesDegrees.end(), std::less_equal<>()))
        throw std::invalid_argument("sphereRayOptics: bin edges must increase from 0 to 180 degrees");

    const Problem problem{m, sigmaA, quadraturePanels(refinement), Binning(binEdgesDegrees)};
    const std::size_t binCount = binEdgesDegrees.size() - 1;
    SphereRayOptics result;
    result.binEdgesDegrees = binEdgesDegrees;
    result.orders.assign(static_cast<std::size_t>(maxOrder) + 1, {{}, std::vector<PowerFraction>(binCount)});
    result.higherOrders.bins.assign(binCount, {});

    RayTotals totals{std::vector<PowerFraction>(static_cast<std::size_t>(maxOrder) + 1), {}, {}, {}};
    for (std::size_t i = 0; i + 1 < problem.panels.size(); ++i)
        integrate(problem.panels[i], problem.panels[i + 1], [&](double thetaI, double weight) {
            addRayTotals(rayAt(thetaI, m, sigmaA), maxOrder, weight, totals);
        });
    for (int order = 0; order <= maxOrder; ++order)
        result.orders[static_cast<std::size_t>(order)].total = totals.orders[static_cast<std::size_t>(order)];
    result.higherOrders.total = totals.higherOrders;
    result.absorbed = totals.absorbed;
    result.escaped = {1.0 - totals.absorbed.s, 1.0 - totals.absorbed.p, 1.0 - totals.absorbed.unpolarisedFresnel};
    result.asymmetry = totals.escapedCosine.intensity() / result.escaped.intensity();
    result.asymmetryUnpolarisedFresnel = totals.escapedCosine.unpolarisedFresnel / result.escaped.unpolarisedFresnel;

    const int lastExact = std::max(maxOrder, kExactlyBinnedOrders);
    for (int order = 0; order <= lastExact; ++order) {
        std::vector<PowerFraction>& bins =
            order <= maxOrder ? result.orders[static_cast<std::size_t>(order)].bins : result.higherOrders.bins;
        binRayOrder(problem, order, bins, result.backscattered);
    }
    result.unresolvedTail = binTail(problem, lastExact, refinement, result.higherOrders.bins, result.backscattered);
    for (std::size_t bin = 0; bin < binCount; ++bin) {
        const double share = (binEdgesDegrees[bin + 1] - binEdgesDegrees[bin]) / 180.0;
        result.higherOrders.bins[bin] += scaled(result.unresolvedTail, share);
    }
    result.backscattered += scaled(result.unresolvedTail, 0.5);

    result.bins = result.higherOrders.bins;
    for (const RayOrderPower& order : result.orders)
        for (std::size_t bin = 0; bin < binCount; ++bin) result.bins[bin] += order.bins[bin];
    return result;
}

// The power of `bins` between two of the edges, in degrees.
inline PowerFraction bandPower(const SphereRayOptics& optics, const std::vector<PowerFraction>& bins,
                               double fromDegrees, double toDegrees) {
    PowerFraction band;
    for (std::size_t bin = 0; bin < bins.size(); ++bin)
        if (optics.binEdgesDegrees[bin] >= fromDegrees && optics.binEdgesDegrees[bin + 1] <= toDegrees)
            band += bins[bin];
    return band;
}

}  // namespace dropscope::testing
