#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/implicit/ImplicitPresets.hpp"
#include "geometry/implicit/ImplicitShape.hpp"
#include "geometry/implicit/ImplicitTolerance.hpp"

#include "geometry/RandomGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace dropscope::testing {

// A random invertible M = R1 diag(s) R2 (det sign random) with singular values in [0.5, 2].
inline Eigen::Matrix3d randomMatrix(Rng& rng) {
    Eigen::Vector3d scales(uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0));
    if (uniform(rng, 0.0, 1.0) < 0.3) scales.x() = -scales.x();
    return randomRotation(rng) * scales.asDiagonal() * randomRotation(rng);
}

inline AffineTransform randomPlacement(Rng& rng, bool similarity = false) {
    const Eigen::Matrix3d m =
        similarity ? Eigen::Matrix3d(uniform(rng, 0.5, 2.0) * randomRotation(rng)) : randomMatrix(rng);
    return {m, randomPoint(rng, 5.0)};
}

// The ellipsoid {r : |S^-1 M^-1 (r - r0)| <= 1}, S = diag(semi-axes): quadric matrix M^-T S^-2 M^-1.
inline Ellipsoid placedEllipsoid(const Eigen::Vector3d& semiAxes, const AffineTransform& t) {
    const Eigen::Matrix3d inverseSquares = semiAxes.cwiseProduct(semiAxes).cwiseInverse().asDiagonal();
    const Eigen::Matrix3d q = t.inverseMatrix().transpose() * inverseSquares * t.inverseMatrix();
    return Ellipsoid::fromMatrix(t.translation(), 0.5 * (q + q.transpose()));
}

// Forwards to a function and counts its value and gradient evaluations (single-threaded use). With
// `convex` false it hides convexCentre(), so shapes built on it take the general (Lipschitz) routes:
// the reference the convex ones are checked against.
class CountingFunction final : public ImplicitFunction {
public:
    explicit CountingFunction(std::shared_ptr<const ImplicitFunction> f, bool convex = true)
        : f_(std::move(f)), convex_(convex) {}
    double value(const Point& r) const override {
        ++evaluations;
        return f_->value(r);
    }
    Eigen::Vector3d gradient(const Point& r) const override {
        ++evaluations;
        return f_->gradient(r);
    }
    double lipschitzBound() const override { return f_->lipschitzBound(); }
    double lipschitzAlong(const Eigen::Vector3d& d) const override { return f_->lipschitzAlong(d); }
    std::optional<Point> convexCenter() const override { return convex_ ? f_->convexCenter() : std::nullopt; }
    Eigen::AlignedBox3d bounds() const override { return f_->bounds(); }
    double characteristicLength() const override { return f_->characteristicLength(); }
    std::string_view presetName() const override { return f_->presetName(); }
    std::vector<PresetParameter> presetParameters() const override { return f_->presetParameters(); }

    mutable long evaluations = 0;

private:
    std::shared_ptr<const ImplicitFunction> f_;
    bool convex_;
};

// Euler's beta function.
inline double beta(double x, double y) { return std::exp(std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y)); }

// Closed-form superellipsoid volume 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2).
inline double superellipsoidVolume(const Eigen::Vector3d& s, const Eigen::Vector2d& e) {
    return 2.0 * s.prod() * e[0] * e[1] * beta(e[0] / 2.0 + 1.0, e[0]) * beta(e[1] / 2.0, e[1] / 2.0);
}

// `build` throws std::invalid_argument with `fragment` in its message.
inline void expectMessage(const std::function<void()>& build, const std::string& fragment) {
    try {
        build();
        ADD_FAILURE() << "no exception, expected: " << fragment;
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
}

}  // namespace dropscope::testing
