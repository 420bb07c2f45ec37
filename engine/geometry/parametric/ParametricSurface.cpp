#include "geometry/parametric/ParametricSurface.hpp"

#include "geometry/parametric/SurfaceTolerance.hpp"

#include <array>
#include <cstddef>

namespace dropscope {

namespace {

// A finite-difference formula along one parameter: d^k f / dx^k ~ sum_i weight[i] f(x + offset[i]).
struct Stencil {
    std::array<double, 4> offset{};
    std::array<double, 4> weight{};
    std::size_t size = 0;
};

struct Axis {
    double lower;
    double upper;
    bool periodic;
    double width() const { return upper - lower; }
};

// x + offset, folded back into the domain along a periodic parameter so that no evaluation leaves it.
double shifted(const Axis& axis, double x, double offset) {
    double y = x + offset;
    if (!axis.periodic) return y;
    if (y < axis.lower) y += axis.width();
    if (y > axis.upper) y -= axis.width();
    return y;
}

// First derivative, second order: central where x +- h stays inside the domain (or the parameter is
// periodic), else the one-sided (-3, 4, -1) / 2h formula pointing into the domain.
Stencil firstDerivative(const Axis& axis, double x, double h) {
    if (axis.periodic || (x - h >= axis.lower && x + h <= axis.upper))
        return {{-h, h, 0.0, 0.0}, {-0.5 / h, 0.5 / h, 0.0, 0.0}, 2};
    const double s = x - h < axis.lower ? h : -h;  // step into the domain
    return {{0.0, s, 2.0 * s, 0.0}, {-1.5 / s, 2.0 / s, -0.5 / s, 0.0}, 3};
}

// Second derivative, second order: central (1, -2, 1) / h^2, or the one-sided (2, -5, 4, -1) / h^2.
Stencil secondDerivative(const Axis& axis, double x, double h) {
    const double h2 = h * h;
    if (axis.periodic || (x - h >= axis.lower && x + h <= axis.upper))
        return {{-h, 0.0, h, 0.0}, {1.0 / h2, -2.0 / h2, 1.0 / h2, 0.0}, 3};
    const double s = x - h < axis.lower ? h : -h;
    return {{0.0, s, 2.0 * s, 3.0 * s}, {2.0 / h2, -5.0 / h2, 4.0 / h2, -1.0 / h2}, 4};
}

Axis uAxis(const ParametricSurface& surface) {
    const ParameterDomain d = surface.domain();
    return {d.u0, d.u1, surface.periodicInU()};
}

Axis vAxis(const ParametricSurface& surface) {
    const ParameterDomain d = surface.domain();
    return {d.v0, d.v1, surface.periodicInV()};
}

}  // namespace

// Steps are fractions of the domain's width (tolerance::surface::kFirstDerivativeStep and
// kSecondDerivativeStep explain the values); near a non-periodic edge the stencils turn one-sided, along
// a periodic parameter they wrap, so r is only ever evaluated inside the domain.
SurfaceJet ParametricSurface::jet(double u, double v) const {
    const Axis ua = uAxis(*this);
    const Axis va = vAxis(*this);
    const Stencil su = firstDerivative(ua, u, tolerance::surface::kFirstDerivativeStep * ua.width());
    const Stencil sv = firstDerivative(va, v, tolerance::surface::kFirstDerivativeStep * va.width());
    SurfaceJet jet{point(u, v), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (std::size_t i = 0; i < su.size; ++i) jet.ru += su.weight[i] * point(shifted(ua, u, su.offset[i]), v);
    for (std::size_t i = 0; i < sv.size; ++i) jet.rv += sv.weight[i] * point(u, shifted(va, v, sv.offset[i]));
    return jet;
}

SurfaceHessians ParametricSurface::hessians(double u, double v) const {
    const Axis ua = uAxis(*this);
    const Axis va = vAxis(*this);
    const double hu = tolerance::surface::kSecondDerivativeStep * ua.width();
    const double hv = tolerance::surface::kSecondDerivativeStep * va.width();
    const Stencil suu = secondDerivative(ua, u, hu);
    const Stencil svv = secondDerivative(va, v, hv);
    const Stencil su = firstDerivative(ua, u, hu);
    const Stencil sv = firstDerivative(va, v, hv);
    SurfaceHessians h{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (std::size_t i = 0; i < suu.size; ++i) h.ruu += suu.weight[i] * point(shifted(ua, u, suu.offset[i]), v);
    for (std::size_t i = 0; i < svv.size; ++i) h.rvv += svv.weight[i] * point(u, shifted(va, v, svv.offset[i]));
    // r_uv: the tensor product of the two first-derivative stencils.
    for (std::size_t i = 0; i < su.size; ++i) {
        const double ui = shifted(ua, u, su.offset[i]);
        for (std::size_t j = 0; j < sv.size; ++j)
            h.ruv += (su.weight[i] * sv.weight[j]) * point(ui, shifted(va, v, sv.offset[j]));
    }
    return h;
}

}  // namespace dropscope
