#include "scene/JsonPath.hpp"
#include "wave/Mie.hpp"
#include "wave/MieNumerics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace mie {

std::size_t termCount(double x) { return static_cast<std::size_t>(std::lround(x + 4.0 * std::cbrt(x) + 2.0)); }

}  // namespace mie

namespace {

void requireValidInput(std::complex<double> m, double x) {
    if (!(x >= kMinSizeParameter && x <= kMaxSizeParameter)) {
        throw std::invalid_argument("size parameter x = " + jsonpath::number(x) + " is outside 1e-3..2e4");
    }
    if (!(m.real() > 0.0) || !std::isfinite(m.real())) {
        throw std::invalid_argument("relative refractive index m = " + jsonpath::number(m.real()) + " + " +
                                    jsonpath::number(m.imag()) + "i must have a finite real part > 0");
    }
    if (!(m.imag() >= 0.0) || !std::isfinite(m.imag())) {
        throw std::invalid_argument("relative refractive index m = " + jsonpath::number(m.real()) + " + " +
                                    jsonpath::number(m.imag()) +
                                    "i must have a finite imaginary part >= 0 (absorption is + i kappa)");
    }
}

// D_n(z) = psi_n'(z) / psi_n(z) for n = 0 .. terms (element n) by downward recurrence,
// D_(n-1) = n/z - 1 / (D_n + n/z) (B&H eq. 4.89), from D = 0 far enough above max(terms, |z|) that the
// start's error has died out (MieNumerics.hpp).
std::vector<std::complex<double>> logarithmicDerivatives(std::complex<double> z, std::size_t terms) {
    const double size = std::abs(z);
    const double airyWidth = std::cbrt(size / 2.0);
    const std::size_t start = std::max(terms, static_cast<std::size_t>(std::ceil(size))) + mie::kStartMargin +
                              static_cast<std::size_t>(std::ceil(mie::kStartAiryWidths * airyWidth));
    std::vector<std::complex<double>> d(terms + 1);
    std::complex<double> current{0.0, 0.0};
    for (std::size_t n = start; n > 0; --n) {
        const std::complex<double> nOverZ = static_cast<double>(n) / z;
        current = nOverZ - 1.0 / (current + nOverZ);  // now D_(n-1)
        if (n - 1 <= terms) d[n - 1] = current;
    }
    return d;
}

}  // namespace

MieCoefficients mieCoefficients(std::complex<double> m, double x) {
    requireValidInput(m, x);
    const std::size_t terms = mie::termCount(x);
    const std::vector<std::complex<double>> d = logarithmicDerivatives(m * x, terms);

    MieCoefficients result{m, x, {}, {}};
    result.a.resize(terms);
    result.b.resize(terms);
    // Riccati-Bessel psi_n(x) = x j_n(x) and chi_n(x) = -x y_n(x) by upward recurrence,
    // f_n = (2n - 1)/x f_(n-1) - f_(n-2) (the spherical Bessel recurrence), from psi_(-1) = cos x, psi_0 = sin x,
    // chi_(-1) = -sin x, chi_0 = cos x; xi_n = psi_n - i chi_n.
    double psiPrevious = std::cos(x);
    double psi = std::sin(x);
    double chiPrevious = -std::sin(x);
    double chi = std::cos(x);
    for (std::size_t n = 1; n <= terms; ++n) {
        const double order = static_cast<double>(n);
        const double factor = (2.0 * order - 1.0) / x;
        const double psiNext = factor * psi - psiPrevious;
        const double chiNext = factor * chi - chiPrevious;
        const std::complex<double> xi{psiNext, -chiNext};
        const std::complex<double> xiPrevious{psi, -chi};
        // a_n and b_n (B&H eq. 4.88)
        const double nOverX = order / x;
        const std::complex<double> da = d[n] / m + nOverX;
        const std::complex<double> db = d[n] * m + nOverX;
        result.a[n - 1] = (da * psiNext - psi) / (da * xi - xiPrevious);
        result.b[n - 1] = (db * psiNext - psi) / (db * xi - xiPrevious);
        psiPrevious = psi;
        psi = psiNext;
        chiPrevious = chi;
        chi = chiNext;
    }
    return result;
}

}  // namespace dropscope
