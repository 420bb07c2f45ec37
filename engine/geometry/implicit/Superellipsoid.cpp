#include "geometry/implicit/Superellipsoid.hpp"

#include "geometry/implicit/ImplicitTolerance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dropscope {

namespace {

// (s^k + t^k)^(1/k) for s, t >= 0 and k >= 1, with the larger term factored out so every power is of
// a number in [0, 1]: no overflow for any k, and an underflowing smaller term is negligible anyway.
double powerNorm(double s, double t, double k) {
    const double largest = std::max(s, t);
    if (largest == 0.0) return 0.0;
    return largest * std::pow(std::pow(s / largest, k) + std::pow(t / largest, k), 1.0 / k);
}

// d/ds (s^k + t^k)^(1/k) = (s / norm)^(k-1), in [0, 1]; 0 where the norm vanishes (a subgradient).
double powerNormSlope(double s, double norm, double k) { return norm > 0.0 ? std::pow(s / norm, k - 1.0) : 0.0; }

double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

}  // namespace

// Why L = sqrt(1/a^2 + 1/b^2 + 1/c^2). With u = |x|/a, v = |y|/b, w = |z|/c, F = ||(N, w)||_q with
// N = ||(u, v)||_p, p = 2/e2, q = 2/e1. For 0 < e <= 2, p, q >= 1: N is a norm of (x, y), and the
// q-norm is monotone in |components|, so F is a norm of r; the body F <= 1 is convex and symmetric.
// Its six vertices (+-a, 0, 0), (0, +-b, 0), (0, 0, +-c) have F = 1, so it contains their convex hull,
// the octahedron |x|/a + |y|/b + |z|/c <= 1, whose gauge G is therefore >= F everywhere. Then, by the
// triangle inequality of the norm F,
//   |f(r1) - f(r2)| = |F(r1) - F(r2)| <= F(r1 - r2) <= G(r1 - r2) <= |r1 - r2| sqrt(1/a^2 + 1/b^2 + 1/c^2)
// (Cauchy-Schwarz last). F(h) itself is the tighter bound along a direction h (lipschitzAlong).
// Also F >= max(N, w) >= max(u, v, w), so the body lies in the box [-a, a] x [-b, b] x [-c, c].
Superellipsoid::Superellipsoid(const Eigen::Vector3d& semiAxes, const Eigen::Vector2d& exponents)
    : semiAxes_(semiAxes), exponents_(exponents) {
    if (!semiAxes.allFinite() || (semiAxes.array() <= 0.0).any())
        throw std::invalid_argument("semi_axes must be finite and > 0");
    using tolerance::implicit::kMaxExponent;
    using tolerance::implicit::kMinExponent;
    for (int i = 0; i < 2; ++i) {
        const double e = exponents[i];
        if (!std::isfinite(e)) throw std::invalid_argument("exponents must be finite");
        if (!(e <= kMaxExponent)) {
            std::ostringstream os;
            os << "exponents must be <= " << kMaxExponent << " (got " << e
               << "): beyond 2 the surface has cusps where no Lipschitz bound exists";
            throw std::invalid_argument(os.str());
        }
        if (!(e >= kMinExponent)) {
            std::ostringstream os;
            os << "exponents must be >= " << kMinExponent << " (got " << e
               << "): smaller ones make edges too sharp to resolve and powers that overflow";
            throw std::invalid_argument(os.str());
        }
    }
    p_ = 2.0 / exponents[1];
    q_ = 2.0 / exponents[0];
    lipschitz_ = semiAxes.cwiseInverse().norm();
}

double Superellipsoid::gauge(const Eigen::Vector3d& r) const {
    const Eigen::Vector3d scaled = r.cwiseAbs().cwiseQuotient(semiAxes_);
    return powerNorm(powerNorm(scaled.x(), scaled.y(), p_), scaled.z(), q_);
}

Eigen::Vector3d Superellipsoid::gradient(const Point& r) const {
    const Eigen::Vector3d scaled = r.cwiseAbs().cwiseQuotient(semiAxes_);
    const double n = powerNorm(scaled.x(), scaled.y(), p_);
    const double f = powerNorm(n, scaled.z(), q_);
    const double slopeN = powerNormSlope(n, f, q_);  // dF/dN
    return {slopeN * powerNormSlope(scaled.x(), n, p_) * sign(r.x()) / semiAxes_.x(),
            slopeN * powerNormSlope(scaled.y(), n, p_) * sign(r.y()) / semiAxes_.y(),
            powerNormSlope(scaled.z(), f, q_) * sign(r.z()) / semiAxes_.z()};
}

std::vector<PresetParameter> Superellipsoid::presetParameters() const {
    return {{"semi_axes", {3}, {semiAxes_.x(), semiAxes_.y(), semiAxes_.z()}},
            {"exponents", {2}, {exponents_.x(), exponents_.y()}}};
}

}  // namespace dropscope
