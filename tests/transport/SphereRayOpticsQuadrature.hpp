#pragma once

// The quadrature behind sphereRayOptics (SphereRayOptics.hpp): integrals over the impact parameter, as
// theta_i, between the impact parameters where a ray order changes angular bin. docs/validation.md, "Ray
// optics of a sphere with s and p tracked", explains it and its accuracy.

#include "transport/SphereRay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace dropscope::testing::sphere_optics_detail {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
// Gauss-Legendre points per quadrature interval; the integrands are analytic in theta_i, so a panel of
// kPanelWidth needs 8, and an interval 16 times shorter (most of those between bin crossings) 4.
constexpr int kGaussPoints = 8;
constexpr int kShortGaussPoints = 4;
// Quadrature panels in theta_i: this wide up to one width before grazing incidence, then halving towards it
// kGradedPanels times (the last panel, 0.05 * 2^-30 = 5e-11 rad, carries 2e-21 of the power).
constexpr double kPanelWidth = 0.05;
constexpr int kGradedPanels = 30;
constexpr double kShortInterval = kPanelWidth / 16;
// Orders up to this one (or the last reported one, if higher) are binned exactly; above it they carry 1e-5
// of the power for water and are binned at kTailSteps impact parameters.
constexpr int kExactlyBinnedOrders = 20;
constexpr int kTailSteps = 20000;
// A tail ray stops being followed when an order carries less than this, or after kMaxTailOrder orders; what
// it still has (2e-12 in all for water, 1.5e-11 for m = 3) is spread evenly in angle, as grazing orders nearly are.
constexpr double kNegligiblePower = 1e-20;
constexpr int kMaxTailOrder = 4096;
// Newton steps on the deviation stop at this change in theta_i: a few rounding units at pi/2.
constexpr double kRootTolerance = 1e-15;

template <int N>
struct GaussRule {
    std::array<double, N> node{};
    std::array<double, N> weight{};
};

// Gauss-Legendre nodes and weights on [-1, 1]: Newton's method on the Legendre polynomial P_N, from the usual
// first guess cos(pi (i + 3/4) / (N + 1/2)) (e.g. Numerical Recipes, "Gauss-Legendre").
template <int N>
const GaussRule<N>& gaussLegendre() {
    static const GaussRule<N> rule = [] {
        GaussRule<N> result;
        for (int i = 0; i < N; ++i) {
            double x = std::cos(kPi * (i + 0.75) / (N + 0.5));
            double derivative = 1.0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double previous = 1.0;
                double current = x;
                for (int k = 2; k <= N; ++k) {
                    const double next = ((2.0 * k - 1.0) * x * current - (k - 1.0) * previous) / k;
                    previous = current;
                    current = next;
                }
                derivative = N * (x * current - previous) / (x * x - 1.0);
                const double step = current / derivative;
                x -= step;
                if (std::abs(step) < 1e-16) break;
            }
            result.node[static_cast<std::size_t>(i)] = x;
            result.weight[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
        }
        return result;
    }();
    return rule;
}

// One ray of the beam, by its angle of incidence.
struct Ray {
    double thetaI;
    double thetaT;
    PolarisedReflectance r;  // at every interface it meets
    double tau;              // transmission of one chord, exp(-2 sigmaA cos theta_t)
};

inline Ray rayAt(double thetaI, double m, double sigmaA) {
    const double cosI = std::cos(thetaI);
    const double cosT = cosRefraction(cosI, m);
    return {thetaI, std::atan2(std::sin(thetaI) / m, cosT), sphereSurfaceReflectance(cosI, m),
            std::exp(-2.0 * sigmaA * cosT)};
}

inline PowerFraction orderShares(const Ray& ray, int order) {
    return {rayOrderShare(ray.r.s, ray.tau, order), rayOrderShare(ray.r.p, ray.tau, order),
            rayOrderShare(ray.r.mean(), ray.tau, order)};
}

inline PowerFraction scaled(PowerFraction power, double factor) {
    return {power.s * factor, power.p * factor, power.unpolarisedFresnel * factor};
}

template <class PerPolarisation>
PowerFraction forEachPolarisation(const Ray& ray, PerPolarisation share) {
    return {share(ray.r.s), share(ray.r.p), share(ray.r.mean())};
}

template <int N, class Integrand>
void integrateWith(double from, double to, Integrand& f) {
    const GaussRule<N>& rule = gaussLegendre<N>();
    const double half = 0.5 * (to - from);
    const double middle = 0.5 * (to + from);
    for (std::size_t i = 0; i < N; ++i) {
        const double thetaI = middle + half * rule.node[i];
        f(thetaI, half * rule.weight[i] * std::sin(2.0 * thetaI));
    }
}

// Adds f(theta_i, weight) over Gauss-Legendre nodes of [from, to], the weight including d(b^2) = sin(2 theta_i)
// d theta_i: kGaussPoints of them, or kShortGaussPoints on an interval shorter than kShortInterval.
template <class Integrand>
void integrate(double from, double to, Integrand&& f) {
    if (to - from < kShortInterval)
        integrateWith<kShortGaussPoints>(from, to, f);
    else
        integrateWith<kGaussPoints>(from, to, f);
}

inline std::vector<double> quadraturePanels(int refinement) {
    std::vector<double> coarse;
    const double graded = kPi / 2 - kPanelWidth;
    const int uniform = static_cast<int>(std::ceil(graded / kPanelWidth));
    for (int i = 0; i < uniform; ++i) coarse.push_back(graded * i / uniform);
    for (int k = 0; k <= kGradedPanels; ++k) coarse.push_back(kPi / 2 - kPanelWidth * std::ldexp(1.0, -k));
    coarse.push_back(kPi / 2);
    std::vector<double> panels;
    for (std::size_t i = 0; i + 1 < coarse.size(); ++i)
        for (int j = 0; j < refinement; ++j) panels.push_back(coarse[i] + (coarse[i + 1] - coarse[i]) * j / refinement);
    panels.push_back(kPi / 2);
    return panels;
}

// The bins of the computation: the caller's edges and 90 degrees, each mapped to the caller's bin.
struct Binning {
    std::vector<double> edges;  // radians
    std::vector<std::size_t> callerBin;
    std::vector<bool> backward;

    explicit Binning(const std::vector<double>& edgesDegrees) {
        const bool hasRightAngle = std::find(edgesDegrees.begin(), edgesDegrees.end(), 90.0) != edgesDegrees.end();
        for (std::size_t i = 0; i < edgesDegrees.size(); ++i) {
            if (i > 0) {
                callerBin.push_back(i - 1);
                backward.push_back(edgesDegrees[i - 1] >= 90.0);
            }
            if (i > 0 && !hasRightAngle && edgesDegrees[i - 1] < 90.0 && edgesDegrees[i] > 90.0) {
                edges.push_back(kPi / 2);
                callerBin.push_back(i - 1);
                backward.push_back(true);
            }
            edges.push_back(edgesDegrees[i] * kDegree);
        }
        edges.back() = kPi;
    }
    std::size_t locate(double angle) const {
        const auto above = std::upper_bound(edges.begin(), edges.end(), angle);
        const auto index =
            std::clamp<std::ptrdiff_t>(above - edges.begin() - 1, 0, static_cast<std::ptrdiff_t>(callerBin.size()) - 1);
        return static_cast<std::size_t>(index);
    }
};

struct Problem {
    double m;
    double sigmaA;
    std::vector<double> panels;
    Binning binning;
};

inline double deviationAt(const Problem& problem, double thetaI, int order) {
    const double cosI = std::cos(thetaI);
    const double thetaT = std::atan2(std::sin(thetaI) / problem.m, cosRefraction(cosI, problem.m));
    return rayOrderDeviation(thetaI, thetaT, order);
}

// dD/dtheta_i, with dtheta_t/dtheta_i = cos(theta_i) / (m cos(theta_t)).
inline double deviationSlope(const Problem& problem, double thetaI, int order) {
    if (order == 0) return -2.0;
    const double cosI = std::cos(thetaI);
    return 2.0 - 2.0 * order * cosI / (problem.m * cosRefraction(cosI, problem.m));
}

// theta_i in [lo, hi] where order's deviation is `target`, the deviation being monotone on [lo, hi] and
// `target` between its values at the ends (`increasing` says which way): Newton from `guess`, bisecting whenever a step
// would leave the bracket.
inline double solveDeviation(const Problem& problem, int order, double target, double lo, double hi, bool increasing,
                             double guess) {
    double thetaI = guess > lo && guess < hi ? guess : 0.5 * (lo + hi);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double residual = deviationAt(problem, thetaI, order) - target;
        if (residual == 0.0) return thetaI;
        ((residual < 0.0) == increasing ? lo : hi) = thetaI;
        double next = thetaI - residual / deviationSlope(problem, thetaI, order);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - thetaI) <= kRootTolerance) return next;
        thetaI = next;
    }
    return thetaI;
}

// The impact parameters (as theta_i) where order's scattering angle crosses a bin edge or turns: between two
// neighbours it stays in one bin. The deviation turns at most once, at the Descartes ray.
inline std::vector<double> binCrossings(const Problem& problem, int order) {
    std::vector<double> monotone = {0.0, kPi / 2};
    if (order >= 2 && problem.m * problem.m < order * order) {
        const double cos2Turn = (problem.m * problem.m - 1.0) / (order * order - 1.0);
        monotone.insert(monotone.begin() + 1, std::acos(std::sqrt(cos2Turn)));
    }
    std::vector<double> crossings = problem.panels;
    crossings.insert(crossings.end(), monotone.begin(), monotone.end());
    for (std::size_t piece = 0; piece + 1 < monotone.size(); ++piece) {
        const double from = monotone[piece];
        const double to = monotone[piece + 1];
        const double deviationFrom = deviationAt(problem, from, order);
        const double deviationTo = deviationAt(problem, to, order);
        const double low = std::min(deviationFrom, deviationTo);
        const double high = std::max(deviationFrom, deviationTo);
        // Deviation in [j pi, (j + 1) pi] scatters at D - j pi for even j and (j + 1) pi - D for odd j.
        std::vector<double> targets;
        for (auto fold = static_cast<int>(std::floor(low / kPi)); fold <= static_cast<int>(std::floor(high / kPi));
             ++fold) {
            for (const double edge : problem.binning.edges) {
                const double target = fold % 2 == 0 ? fold * kPi + edge : (fold + 1) * kPi - edge;
                if (target > low && target < high) targets.push_back(target);
            }
        }
        // In the order they are met from `from`, each solved from the last one's root onwards.
        std::sort(targets.begin(), targets.end());
        targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
        if (deviationTo < deviationFrom) std::reverse(targets.begin(), targets.end());
        double last = from;
        for (const double target : targets) {
            const double guess =
                last + (target - deviationAt(problem, last, order)) / deviationSlope(problem, last, order);
            last = solveDeviation(problem, order, target, last, to, deviationTo > deviationFrom, guess);
            crossings.push_back(last);
        }
    }
    std::sort(crossings.begin(), crossings.end());
    return crossings;
}

// One order's power in each bin: integrated exactly between the impact parameters where it changes bin.
inline void binRayOrder(const Problem& problem, int order, std::vector<PowerFraction>& bins,
                        PowerFraction& backscattered) {
    const std::vector<double> crossings = binCrossings(problem, order);
    for (std::size_t i = 0; i + 1 < crossings.size(); ++i) {
        if (!(crossings[i + 1] > crossings[i])) continue;
        const double middle = 0.5 * (crossings[i] + crossings[i + 1]);
        const std::size_t bin = problem.binning.locate(scatteringAngle(deviationAt(problem, middle, order)));
        PowerFraction power;
        integrate(crossings[i], crossings[i + 1], [&](double thetaI, double weight) {
            power += scaled(orderShares(rayAt(thetaI, problem.m, problem.sigmaA), order), weight);
        });
        bins[problem.binning.callerBin[bin]] += power;
        if (problem.binning.backward[bin]) backscattered += power;
    }
}

// Orders above `lastExact`, ray by ray at kTailSteps * refinement midpoints of theta_i, each order's power
// into the bin of its scattering angle; returns what is left past the orders followed. From one order to the
// next the power is multiplied by R tau and the deviation grows by pi - 2 theta_t.
inline PowerFraction binTail(const Problem& problem, int lastExact, int refinement, std::vector<PowerFraction>& bins,
                             PowerFraction& backscattered) {
    PowerFraction unresolved;
    const int steps = kTailSteps * refinement;
    const double step = kPi / 2 / steps;
    for (int i = 0; i < steps; ++i) {
        const Ray ray = rayAt((i + 0.5) * step, problem.m, problem.sigmaA);
        const PowerFraction ratio = forEachPolarisation(ray, [&](double r) { return r * ray.tau; });
        int order = lastExact + 1;
        PowerFraction power = scaled(orderShares(ray, order), std::sin(2.0 * ray.thetaI) * step);
        double deviation = rayOrderDeviation(ray.thetaI, ray.thetaT, order);
        for (; order <= kMaxTailOrder && std::max(power.s, power.p) >= kNegligiblePower; ++order) {
            const std::size_t bin = problem.binning.locate(scatteringAngle(deviation));
            bins[problem.binning.callerBin[bin]] += power;
            if (problem.binning.backward[bin]) backscattered += power;
            power = {power.s * ratio.s, power.p * ratio.p, power.unpolarisedFresnel * ratio.unpolarisedFresnel};
            deviation += kPi - 2.0 * ray.thetaT;
        }
        // `power` is order `order`'s; with all above it, power / (1 - R tau).
        unresolved += {power.s / (1.0 - ratio.s), power.p / (1.0 - ratio.p),
                       power.unpolarisedFresnel / (1.0 - ratio.unpolarisedFresnel)};
    }
    return unresolved;
}

// Totals that need no bins, per ray in closed form: every order, the orders above maxOrder, the absorbed
// power and the numerator of g.
struct RayTotals {
    std::vector<PowerFraction> orders;
    PowerFraction higherOrders;
    PowerFraction absorbed;
    PowerFraction escapedCosine;  // sum of P cos(theta) over every order
};

inline void addRayTotals(const Ray& ray, int maxOrder, double weight, RayTotals& totals) {
    for (int order = 0; order <= maxOrder; ++order)
        totals.orders[static_cast<std::size_t>(order)] += scaled(orderShares(ray, order), weight);
    const double tau = ray.tau;
    totals.higherOrders += scaled(
        forEachPolarisation(ray, [&](double r) { return rayOrderShare(r, tau, maxOrder + 1) / (1.0 - r * tau); }),
        weight);
    // Every chord absorbs 1 - tau of what enters it: (1 - R)(1 - tau) / (1 - R tau) in all.
    totals.absorbed +=
        scaled(forEachPolarisation(ray, [&](double r) { return (1 - r) * (1 - tau) / (1 - r * tau); }), weight);
    // sum over p >= 1 of (1 - R)^2 R^(p-1) tau^p e^(i D_p), D_p = D_1 + (p - 1) phi: a geometric series.
    const std::complex<double> firstChord = std::polar(1.0, rayOrderDeviation(ray.thetaI, ray.thetaT, 1));
    const std::complex<double> turn = std::polar(1.0, kPi - 2.0 * ray.thetaT);
    const double reflectedCosine = std::cos(rayOrderDeviation(ray.thetaI, ray.thetaT, 0));
    totals.escapedCosine += scaled(
        forEachPolarisation(ray,
                            [&](double r) {
                                const double through = (1 - r) * (1 - r) * tau;
                                return r * reflectedCosine + std::real(through * firstChord / (1.0 - r * tau * turn));
                            }),
        weight);
}

}  // namespace dropscope::testing::sphere_optics_detail
