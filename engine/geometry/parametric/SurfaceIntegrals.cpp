#include "geometry/parametric/SurfaceIntegrals.hpp"

#include "geometry/parametric/BezierSurface.hpp"
#include "geometry/parametric/SurfaceTolerance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dropscope {

namespace {

// The 15-point Gauss-Kronrod rule on [-1, 1] with its embedded 7-point Gauss rule (QUADPACK's qk15):
// nodes, Kronrod weights, and Gauss weights (0 at the Kronrod-only nodes).
constexpr std::array<double, 15> kNodes = {-0.991455371120812639206854697526329, -0.949107912342758524526189684047851,
                                           -0.864864423359769072789712788640926, -0.741531185599394439863864773280788,
                                           -0.586087235467691130294144845693013, -0.405845151377397166906606412076961,
                                           -0.207784955007898467600689403773245, 0.0,
                                           0.207784955007898467600689403773245,  0.405845151377397166906606412076961,
                                           0.586087235467691130294144845693013,  0.741531185599394439863864773280788,
                                           0.864864423359769072789712788640926,  0.949107912342758524526189684047851,
                                           0.991455371120812639206854697526329};
constexpr std::array<double, 15> kKronrod = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
    0.140653259715525918745189590510238, 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714, 0.204432940075298892414161999234649,
    0.190350578064785409913256402421014, 0.169004726639267902826583426598550, 0.140653259715525918745189590510238,
    0.104790010322250183839876322541518, 0.063092092629978553290700663189204, 0.022935322010529224963732008058970};
constexpr std::array<double, 15> kGauss = {
    0.0, 0.129484966168869693270611432679082, 0.0, 0.279705391489276667901467771423780,
    0.0, 0.381830050505118944950369775488975, 0.0, 0.417959183673469387755102040816327,
    0.0, 0.381830050505118944950369775488975, 0.0, 0.279705391489276667901467771423780,
    0.0, 0.129484966168869693270611432679082, 0.0};
constexpr std::size_t kRule = kNodes.size();

struct Cell {
    double u0, u1, v0, v1;
    double value = 0.0;   // the tensor Kronrod estimate
    double error = 0.0;   // |Kronrod - Gauss|
    double errorU = 0.0;  // the part of it due to the rule along u (Kronrod along v), and vice versa
    double errorV = 0.0;
    double absValue = 0.0;  // the Kronrod estimate of the integral of |integrand|: the rounding scale
};

bool lessError(const Cell& a, const Cell& b) { return a.error < b.error; }

template <class Integrand>
void evaluate(const ParametricSurface& surface, const Integrand& integrand, Cell& cell) {
    const double hu = 0.5 * (cell.u1 - cell.u0), hv = 0.5 * (cell.v1 - cell.v0);
    const double mu = 0.5 * (cell.u0 + cell.u1), mv = 0.5 * (cell.v0 + cell.v1);
    double kk = 0.0, gg = 0.0, gk = 0.0, kg = 0.0, absolute = 0.0;
    for (std::size_t i = 0; i < kRule; ++i) {
        const double u = mu + hu * kNodes[i];
        double k = 0.0, g = 0.0, a = 0.0;  // the rules along v at this u
        for (std::size_t j = 0; j < kRule; ++j) {
            const double f = integrand(surface.jet(u, mv + hv * kNodes[j]));
            k += kKronrod[j] * f;
            g += kGauss[j] * f;
            a += kKronrod[j] * std::abs(f);
        }
        kk += kKronrod[i] * k;
        gg += kGauss[i] * g;
        gk += kGauss[i] * k;
        kg += kKronrod[i] * g;
        absolute += kKronrod[i] * a;
    }
    const double jacobian = hu * hv;
    cell.value = kk * jacobian;
    cell.error = std::abs(kk - gg) * jacobian;
    cell.errorU = std::abs(kk - gk) * jacobian;
    cell.errorV = std::abs(kk - kg) * jacobian;
    cell.absValue = absolute * jacobian;
}

// Cells per direction to start from: at least kQuadratureMinInitialCells, and never straddling a seam
// between Bezier patches (the integrand is only continuous, or not even that, across one).
std::array<int, 2> initialCells(const ParametricSurface& surface) {
    constexpr int minimum = tolerance::surface::kQuadratureMinInitialCells;
    if (const auto* bezier = dynamic_cast<const BezierSurface*>(&surface)) {
        const int rows = static_cast<int>(bezier->rows()), columns = static_cast<int>(bezier->columns());
        return {rows * ((minimum + rows - 1) / rows), columns * ((minimum + columns - 1) / columns)};
    }
    return {minimum, minimum};
}

// Global adaptive cubature: split the cell of largest error estimate (along the direction responsible
// for it, or both) until the summed estimate is below the requested relative tolerance.
template <class Integrand>
QuadratureResult integrate(const ParametricSurface& surface, const Integrand& integrand, double relativeTolerance) {
    const ParameterDomain d = surface.domain();
    const auto [nu, nv] = initialCells(surface);
    std::vector<Cell> heap;
    QuadratureResult running;  // sums over the cells in the heap, kept up to date as cells are split
    double absTotal = 0.0;
    const auto add = [&](double u0, double u1, double v0, double v1) {
        Cell cell{u0, u1, v0, v1};
        evaluate(surface, integrand, cell);
        running.value += cell.value;
        running.errorEstimate += cell.error;
        absTotal += cell.absValue;
        heap.push_back(cell);
        std::push_heap(heap.begin(), heap.end(), lessError);
    };
    const auto at = [](double a, double b, int k, int n) {
        return k == n ? b : a + (b - a) * static_cast<double>(k) / static_cast<double>(n);
    };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
            add(at(d.u0, d.u1, i, nu), at(d.u0, d.u1, i + 1, nu), at(d.v0, d.v1, j, nv), at(d.v0, d.v1, j + 1, nv));

    const auto target = [&]() {
        return std::max(relativeTolerance * std::abs(running.value),
                        tolerance::surface::kQuadratureRoundoffFloor * absTotal);
    };
    while (running.errorEstimate > target() &&
           heap.size() < static_cast<std::size_t>(tolerance::surface::kQuadratureMaxCells)) {
        std::pop_heap(heap.begin(), heap.end(), lessError);
        const Cell worst = heap.back();
        heap.pop_back();
        running.value -= worst.value;
        running.errorEstimate -= worst.error;
        absTotal -= worst.absValue;
        const double larger = std::max(worst.errorU, worst.errorV);
        const bool splitU = worst.errorU >= tolerance::surface::kQuadratureSplitBothRatio * larger;
        const bool splitV = worst.errorV >= tolerance::surface::kQuadratureSplitBothRatio * larger;
        const double um = 0.5 * (worst.u0 + worst.u1), vm = 0.5 * (worst.v0 + worst.v1);
        if (splitU && splitV) {
            add(worst.u0, um, worst.v0, vm);
            add(um, worst.u1, worst.v0, vm);
            add(worst.u0, um, vm, worst.v1);
            add(um, worst.u1, vm, worst.v1);
        } else if (splitU) {
            add(worst.u0, um, worst.v0, worst.v1);
            add(um, worst.u1, worst.v0, worst.v1);
        } else {
            add(worst.u0, worst.u1, worst.v0, vm);
            add(worst.u0, worst.u1, vm, worst.v1);
        }
    }
    // A fresh sum: the running one has absorbed the rounding of every subtraction.
    QuadratureResult result;
    for (const Cell& c : heap) {
        result.value += c.value;
        result.errorEstimate += c.error;
    }
    return result;
}

}  // namespace

QuadratureResult surfaceAreaIntegral(const ParametricSurface& surface, const Eigen::Matrix3d& m,
                                     double relativeTolerance) {
    // M a x M b = cof(M) (a x b), cof(M) = det(M) M^-T, whose columns are the cross products of M's
    // columns: finite even for a singular M (seed 000 eq. 1.68).
    Eigen::Matrix3d cofactor;
    cofactor.col(0) = m.col(1).cross(m.col(2));
    cofactor.col(1) = m.col(2).cross(m.col(0));
    cofactor.col(2) = m.col(0).cross(m.col(1));
    return integrate(
        surface, [&](const SurfaceJet& j) { return (cofactor * j.ru.cross(j.rv)).norm(); }, relativeTolerance);
}

QuadratureResult signedVolumeIntegral(const ParametricSurface& surface, double relativeTolerance) {
    // seed 000 eq. 1.73: z times the z component of r_u x r_v.
    return integrate(
        surface, [](const SurfaceJet& j) { return j.r.z() * (j.ru.x() * j.rv.y() - j.rv.x() * j.ru.y()); },
        relativeTolerance);
}

}  // namespace dropscope
