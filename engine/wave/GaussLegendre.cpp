#include "wave/GaussLegendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

// P_n(t) and its derivative by the three-term recurrence (n >= 1).
struct LegendreValue {
    double value;
    double derivative;
};
LegendreValue legendre(std::size_t n, double t) {
    double previous = 1.0;
    double current = t;
    for (std::size_t k = 2; k <= n; ++k) {
        const double order = static_cast<double>(k);
        const double next = ((2.0 * order - 1.0) * t * current - (order - 1.0) * previous) / order;
        previous = current;
        current = next;
    }
    const double order = static_cast<double>(n);
    return {current, order * (t * current - previous) / (t * t - 1.0)};
}

// Newton steps until the step is below this: the nodes are then good to an ulp or two.
constexpr double kNewtonStep = 1e-15;
constexpr int kMaxNewtonSteps = 100;

}  // namespace

GaussLegendreRule gaussLegendre(std::size_t order) {
    if (order == 0) throw std::invalid_argument("a Gauss-Legendre rule needs at least one node");
    GaussLegendreRule rule{std::vector<double>(order), std::vector<double>(order)};
    const double n = static_cast<double>(order);
    for (std::size_t i = 0; i < (order + 1) / 2; ++i) {
        // Tricomi's first guess of the i-th largest root, then Newton.
        double t = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (n + 0.5));
        LegendreValue p = legendre(order, t);
        for (int step = 0; step < kMaxNewtonSteps; ++step) {
            const double delta = p.value / p.derivative;
            t -= delta;
            p = legendre(order, t);
            if (std::abs(delta) < kNewtonStep) break;
        }
        const double weight = 2.0 / ((1.0 - t * t) * p.derivative * p.derivative);
        rule.nodes[order - 1 - i] = t;
        rule.nodes[i] = -t;
        rule.weights[order - 1 - i] = weight;
        rule.weights[i] = weight;
    }
    if (order % 2 == 1) rule.nodes[order / 2] = 0.0;
    return rule;
}

}  // namespace dropscope
