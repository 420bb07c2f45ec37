#include "geometry/implicit/ConvexBody.hpp"

#include "geometry/implicit/ImplicitTolerance.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace dropscope {

namespace {

using namespace tolerance::implicit;

struct QuadratureRule {
    std::vector<double> nodes;    // in (0, 1)
    std::vector<double> weights;  // summing to 1
};

// Gauss-Legendre on [0, 1]: Newton on P_n from the Chebyshev-like guesses cos(pi (i + 3/4) / (n + 1/2)).
QuadratureRule gaussLegendre(int n) {
    QuadratureRule rule;
    const auto size = static_cast<std::size_t>(n);
    rule.nodes.resize(size);
    rule.weights.resize(size);
    const double nd = static_cast<double>(n);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (nd + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < kLegendreNewtonIterations; ++iteration) {
            double p0 = 1.0;
            double p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double kd = static_cast<double>(k);
                const double p2 = ((2.0 * kd - 1.0) * x * p1 - (kd - 1.0) * p0) / kd;
                p0 = p1;
                p1 = p2;
            }
            derivative = nd * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) <= kLegendreNodeTolerance) break;
        }
        const auto index = static_cast<std::size_t>(i);
        rule.nodes[index] = 0.5 * (1.0 - x);
        rule.weights[index] = 1.0 / ((1.0 - x * x) * derivative * derivative);  // 2 / (...) on [-1, 1], halved
    }
    return rule;
}

struct PanelSums {
    double volume = 0.0;
    double area = 0.0;
};

PanelSums radialSums(const ImplicitFunction& f, const Point& center, const Eigen::Vector3d& half,
                     const AffineTransform& transform, double band, int order) {
    const QuadratureRule rule = gaussLegendre(order);
    const double detH = half.prod();
    const double areaScale = std::abs(transform.determinant());
    const Eigen::Matrix3d inverseTranspose = transform.inverseMatrix().transpose();
    PanelSums sums;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3;
        const int j = (k + 2) % 3;
        for (int panel = 0; panel < 8; ++panel) {
            const double sigma = (panel & 1) ? -1.0 : 1.0;
            const double signS = (panel & 2) ? -1.0 : 1.0;
            const double signT = (panel & 4) ? -1.0 : 1.0;
            for (std::size_t a = 0; a < rule.nodes.size(); ++a) {
                for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
                    Eigen::Vector3d cube = Eigen::Vector3d::Zero();
                    cube[k] = sigma;
                    cube[i] = signS * rule.nodes[a];
                    cube[j] = signT * rule.nodes[b];
                    const Eigen::Vector3d u = half.cwiseProduct(cube);
                    const RadialExit exit = radialExit(f, center, u, 1.0, kRefineBands * band / u.norm());
                    const double gradientNorm = exit.gradient.norm();
                    if (!(gradientNorm > 0.0)) continue;  // cannot happen on the surface of a convex f
                    const Eigen::Vector3d normal = exit.gradient / gradientNorm;
                    const double weight = rule.weights[a] * rule.weights[b] * detH;
                    const double lambda2 = exit.t * exit.t;
                    sums.volume += weight * lambda2 * exit.t / 3.0;
                    sums.area += weight * lambda2 / u.dot(normal) * areaScale * (inverseTranspose * normal).norm();
                }
            }
        }
    }
    return sums;
}

}  // namespace

RadialExit radialExit(const ImplicitFunction& f, const Point& center, const Eigen::Vector3d& u, double tOut,
                      double tolerance) {
    double lo = 0.0;
    double hi = tOut;
    double t = tOut;
    RadialExit exit;
    for (int iteration = 0; iteration < kMaxRefineIterations; ++iteration) {
        const Point r = center + t * u;
        const double g = f.value(r);
        exit = {t, f.gradient(r)};
        if (g >= 0.0) {
            hi = t;
        } else {
            lo = t;  // rounding put a Newton point just inside: Newton from here overshoots to >= the root
        }
        if (g == 0.0 || hi - lo <= tolerance) break;
        const double slope = exit.gradient.dot(u);
        double next = slope > 0.0 ? t - g / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= tolerance) {
            exit.t = next;  // the gradient of a point within `tolerance`
            break;
        }
        t = next;
    }
    return exit;
}

BodyIntegrals convexBodyIntegrals(const ImplicitFunction& f, const Point& center, const Eigen::AlignedBox3d& bounds,
                                  const AffineTransform& transform, double band, int order) {
    const Eigen::Vector3d half = (center - bounds.min()).cwiseMax(bounds.max() - center);
    const PanelSums coarse = radialSums(f, center, half, transform, band, order);
    const PanelSums fine = radialSums(f, center, half, transform, band, 2 * order);
    const auto estimate = [](double fineValue, double coarseValue) {
        return IntegralEstimate{fineValue, kConvexIntegralSafety * std::abs(fineValue - coarseValue) +
                                               kConvexIntegralFloor * std::abs(fineValue)};
    };
    return {estimate(fine.volume, coarse.volume), estimate(fine.area, coarse.area)};
}

}  // namespace dropscope
