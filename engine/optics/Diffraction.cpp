#include "optics/Diffraction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dropscope {
namespace {

// F on u = 0, h, 2h, ... up to kTableEnd: a bracket and a start for Newton's method on the exact F. Beyond
// kTableEnd (p > 0.9987) the bracket comes from the asymptote 1 - F ~ 2 / (pi u).
constexpr double kTableStep = 0.05;
constexpr double kTableEnd = 500.0;
// Newton stops when a step moves u by less than this, relative; 1e-13 is far below any effect on a direction.
constexpr double kQuantileTolerance = 1e-13;

const std::vector<double>& encircledEnergyTable() {
    static const std::vector<double> table = [] {
        const auto count = static_cast<std::size_t>(kTableEnd / kTableStep) + 1;
        std::vector<double> values(count);
        for (std::size_t i = 0; i < count; ++i) values[i] = airyEncircledEnergy(static_cast<double>(i) * kTableStep);
        return values;
    }();
    return table;
}

// The density dF/du = 2 J1(u)^2 / u (1/2 u near 0, where J1(u) ~ u / 2).
double encircledEnergyDensity(double u) {
    if (u < 1e-8) return 0.5 * u;
    const double j1 = std::cyl_bessel_j(1.0, u);
    return 2.0 * j1 * j1 / u;
}

// The root of F(u) = p in [lo, hi] (F(lo) <= p <= F(hi)) by Newton's method, kept in the bracket by bisection.
double solveInBracket(double p, double lo, double hi, double start) {
    double u = std::clamp(start, lo, hi);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double residual = airyEncircledEnergy(u) - p;
        if (residual == 0.0) return u;
        if (residual < 0.0) {
            lo = u;
        } else {
            hi = u;
        }
        const double slope = encircledEnergyDensity(u);
        double next = slope > 0.0 ? u - residual / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - u) <= kQuantileTolerance * std::max(1.0, u) ||
            hi - lo <= kQuantileTolerance * std::max(1.0, u))
            return next;
        u = next;
    }
    return u;
}

}  // namespace

double airyEncircledEnergy(double u) {
    if (u <= 0.0) return 0.0;
    // Near 0, 1 - J0^2 - J1^2 = u^2/4 - u^4/32 + ... would cancel: the series to u^6.
    if (u < 1e-3) return u * u / 4.0 * (1.0 - u * u / 8.0 * (1.0 - 5.0 * u * u / 72.0));
    const double j0 = std::cyl_bessel_j(0.0, u);
    const double j1 = std::cyl_bessel_j(1.0, u);
    return 1.0 - j0 * j0 - j1 * j1;
}

double airyRadiusQuantile(double p) {
    if (!(p >= 0.0 && p < 1.0)) throw std::invalid_argument("airyRadiusQuantile: p must be in [0, 1)");
    if (p == 0.0) return 0.0;
    const std::vector<double>& table = encircledEnergyTable();
    if (p <= table.back()) {
        // F is non-decreasing: the first node with F >= p closes the bracket.
        const auto above = std::lower_bound(table.begin(), table.end(), p);
        const auto i = static_cast<std::size_t>(above - table.begin());
        const double hi = static_cast<double>(i) * kTableStep;
        const double lo = i == 0 ? 0.0 : hi - kTableStep;
        const double fLo = i == 0 ? 0.0 : table[i - 1];
        const double fraction = *above > fLo ? (p - fLo) / (*above - fLo) : 0.5;
        return solveInBracket(p, lo, hi, lo + fraction * kTableStep);
    }
    const double guess = 2.0 / (std::numbers::pi * (1.0 - p));
    double hi = std::max(2.0 * guess, 2.0 * kTableEnd);
    for (int doubling = 0; doubling < 64 && airyEncircledEnergy(hi) < p; ++doubling) hi *= 2.0;
    return solveInBracket(p, kTableEnd, hi, std::max(guess, kTableEnd));
}

}  // namespace dropscope
