#include "wave/GaussLegendre.hpp"
#include "wave/Mie.hpp"
#include "wave/MieNumerics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace dropscope {

namespace {

// Nodes evaluated together: the loop over them is the one the compiler vectorises.
constexpr std::size_t kBlock = 8;

// The series' coefficients, one array per part, so that the kernel streams through them: c_n a_n and c_n b_n
// with c_n = (2n+1)/(n(n+1)), and the pi_n recurrence's factors (2n+1)/n and (n+1)/n.
struct SeriesTerms {
    std::vector<double> aRe, aIm, bRe, bIm, order, rise, fall;

    explicit SeriesTerms(const MieCoefficients& coefficients) {
        const std::size_t terms = coefficients.a.size();
        for (auto* column : {&aRe, &aIm, &bRe, &bIm, &order, &rise, &fall}) column->resize(terms);
        for (std::size_t i = 0; i < terms; ++i) {
            const double n = static_cast<double>(i + 1);
            const double c = (2.0 * n + 1.0) / (n * (n + 1.0));
            aRe[i] = c * coefficients.a[i].real();
            aIm[i] = c * coefficients.a[i].imag();
            bRe[i] = c * coefficients.b[i].real();
            bIm[i] = c * coefficients.b[i].imag();
            order[i] = n;
            rise[i] = (2.0 * n + 1.0) / n;
            fall[i] = (n + 1.0) / n;
        }
    }
};

// The Mueller elements S11, S12, S33, S34 at kBlock values of cos theta, weighted and summed: one pass
// over the series computes pi_n and tau_n once per node (B&H eqs. 4.47, 4.74, 4.77).
std::array<double, 4> weightedMuellerSum(const SeriesTerms& series, const std::array<double, kBlock>& mu,
                                         const std::array<double, kBlock>& weight) {
    std::array<double, kBlock> piPrevious{}, pi{}, s1Re{}, s1Im{}, s2Re{}, s2Im{};
    pi.fill(1.0);
    const std::size_t terms = series.order.size();
    for (std::size_t i = 0; i < terms; ++i) {
        const double n = series.order[i];
        const double nextOrder = n + 1.0;
        const double aRe = series.aRe[i], aIm = series.aIm[i], bRe = series.bRe[i], bIm = series.bIm[i];
        const double rise = series.rise[i], fall = series.fall[i];
        for (std::size_t k = 0; k < kBlock; ++k) {
            const double muPi = mu[k] * pi[k];
            const double tau = n * muPi - nextOrder * piPrevious[k];
            s1Re[k] += aRe * pi[k] + bRe * tau;
            s1Im[k] += aIm * pi[k] + bIm * tau;
            s2Re[k] += aRe * tau + bRe * pi[k];
            s2Im[k] += aIm * tau + bIm * pi[k];
            const double piNext = rise * muPi - fall * piPrevious[k];
            piPrevious[k] = pi[k];
            pi[k] = piNext;
        }
    }
    std::array<double, 4> sum{};
    for (std::size_t k = 0; k < kBlock; ++k) {
        const MieMueller mueller = mieMueller({{s1Re[k], s1Im[k]}, {s2Re[k], s2Im[k]}});
        sum[0] += weight[k] * mueller.s11;
        sum[1] += weight[k] * mueller.s12;
        sum[2] += weight[k] * mueller.s33;
        sum[3] += weight[k] * mueller.s34;
    }
    return sum;
}

}  // namespace

MieAngularBins mieAngularBins(const MieCoefficients& coefficients, std::size_t bins) {
    MieAngularBins result{std::vector<double>(bins), std::vector<double>(bins), std::vector<double>(bins),
                          std::vector<double>(bins)};
    if (bins == 0) return result;
    const double width = std::numbers::pi / static_cast<double>(bins);
    const double x = coefficients.x;
    // Composite Gauss-Legendre in theta: `panels` panels of `order` nodes per bin (MieNumerics.hpp).
    const auto target = static_cast<std::size_t>(std::ceil(mie::kNodesPerPhase * x * width)) + mie::kExtraNodes;
    const std::size_t panels = (target + mie::kMaxPanelOrder - 1) / mie::kMaxPanelOrder;
    const std::size_t order = (target + panels - 1) / panels;
    const GaussLegendreRule rule = gaussLegendre(order);
    const double panelWidth = width / static_cast<double>(panels);
    const SeriesTerms series(coefficients);
    const std::size_t nodes = panels * order;
    // Per bin: (2 / x^2) * integral of S_ij sin theta d theta = integral over the solid angle / (pi x^2).
    const double scale = 2.0 / (x * x) * 0.5 * panelWidth;

    const double work = static_cast<double>(nodes * bins * series.order.size());
#pragma omp parallel for schedule(dynamic) if (work > mie::kParallelTermEvaluations)
    for (std::size_t bin = 0; bin < bins; ++bin) {
        const double binStart = static_cast<double>(bin) * width;
        std::array<double, 4> total{};
        for (std::size_t first = 0; first < nodes; first += kBlock) {
            std::array<double, kBlock> mu{}, weight{};  // padding nodes keep weight 0
            for (std::size_t k = 0; k < kBlock && first + k < nodes; ++k) {
                const std::size_t panel = (first + k) / order;
                const std::size_t node = (first + k) % order;
                const double panelCentre = binStart + (static_cast<double>(panel) + 0.5) * panelWidth;
                const double theta = panelCentre + 0.5 * panelWidth * rule.nodes[node];
                mu[k] = std::cos(theta);
                weight[k] = rule.weights[node] * std::sin(theta);
            }
            const std::array<double, 4> block = weightedMuellerSum(series, mu, weight);
            for (std::size_t j = 0; j < 4; ++j) total[j] += block[j];
        }
        result.fraction[bin] = scale * total[0];
        result.s12[bin] = scale * total[1];
        result.s33[bin] = scale * total[2];
        result.s34[bin] = scale * total[3];
    }
    return result;
}

}  // namespace dropscope
